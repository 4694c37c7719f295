// A build without CUDA: sharing GL buffers with CUDA is impossible, said at construction.
#include "cuda/gl_buffer_interop.h"

#if !GLINT_HAVE_CUDA
#include "core/error.h"

namespace glint::cuda {

struct GlBufferInterop::Resources {};

GlBufferInterop::GlBufferInterop(std::span<const InteropBuffer>) {
  fail("GL/CUDA interop: glint was built without CUDA (GLINT_CUDA=OFF or no nvcc at configure time)");
}
GlBufferInterop::~GlBufferInterop() = default;
std::vector<void*> GlBufferInterop::map(void*) { return {}; }
void GlBufferInterop::unmap(void*) {}
std::uint64_t GlBufferInterop::round_trips() { return 0; }  // nothing is ever mapped

}  // namespace glint::cuda
#endif
