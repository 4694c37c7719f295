// A build without CUDA has no device to choose.
#include "cuda/device_select.h"

#if !GLINT_HAVE_CUDA
namespace glint::cuda {

void use_device(int /*ordinal*/) {}

int visible_device_count() { return 0; }

}  // namespace glint::cuda
#endif
