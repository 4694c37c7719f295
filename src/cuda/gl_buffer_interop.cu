#include "cuda/gl_buffer_interop.h"

#include "cuda/cuda_check.h"

#include <epoxy/gl.h>  // before cuda_gl_interop.h, which needs GL types (epoxy stands in for GL/gl.h)
#include <cuda_gl_interop.h>

#include <string>

namespace glint::cuda {

struct GlBufferInterop::Resources {
  std::vector<cudaGraphicsResource_t> handles;
};

namespace {

unsigned int register_flags(InteropAccess access) {
  switch (access) {
    case InteropAccess::read_only: return cudaGraphicsRegisterFlagsReadOnly;
    case InteropAccess::write_discard: return cudaGraphicsRegisterFlagsWriteDiscard;
    case InteropAccess::read_write: return cudaGraphicsRegisterFlagsNone;
  }
  return cudaGraphicsRegisterFlagsNone;
}

int open_maps = 0;              // GlBufferInterops mapped now
std::uint64_t round_trip_count = 0;  // outermost maps so far

}  // namespace

std::uint64_t GlBufferInterop::round_trips() { return round_trip_count; }

GlBufferInterop::GlBufferInterop(std::span<const InteropBuffer> buffers) : resources_(std::make_unique<Resources>()) {
  for (const InteropBuffer& buffer : buffers) {
    cudaGraphicsResource_t handle = nullptr;
    const cudaError_t status = cudaGraphicsGLRegisterBuffer(&handle, buffer.gl_buffer, register_flags(buffer.access));
    if (status != cudaSuccess) {
      cudaGetLastError();
      for (cudaGraphicsResource_t registered : resources_->handles) cudaGraphicsUnregisterResource(registered);
      fail_message("CUDA cannot share GL buffer " + std::to_string(buffer.gl_buffer) + ": " +
                   cudaGetErrorString(status) + " (is the GL context on the same NVIDIA GPU as CUDA?)");
    }
    resources_->handles.push_back(handle);
  }
}

GlBufferInterop::~GlBufferInterop() {
  if (mapped_) --open_maps;
  if (mapped_) cudaGraphicsUnmapResources(static_cast<int>(resources_->handles.size()), resources_->handles.data(), nullptr);
  for (cudaGraphicsResource_t handle : resources_->handles) cudaGraphicsUnregisterResource(handle);
}

std::vector<void*> GlBufferInterop::map(void* stream) {
  if (mapped_) fail_message("GL/CUDA interop: buffers mapped twice");
  auto* handles = resources_->handles.data();
  const int count = static_cast<int>(resources_->handles.size());
  GLINT_CUDA_CHECK(cudaGraphicsMapResources(count, handles, static_cast<cudaStream_t>(stream)));
  mapped_ = true;
  if (open_maps++ == 0) ++round_trip_count;
  std::vector<void*> pointers(resources_->handles.size(), nullptr);
  for (std::size_t i = 0; i < pointers.size(); ++i) {
    std::size_t bytes = 0;
    GLINT_CUDA_CHECK(cudaGraphicsResourceGetMappedPointer(&pointers[i], &bytes, handles[i]));
  }
  return pointers;
}

void GlBufferInterop::unmap(void* stream) {
  if (!mapped_) return;
  mapped_ = false;
  --open_maps;
  GLINT_CUDA_CHECK(cudaGraphicsUnmapResources(static_cast<int>(resources_->handles.size()), resources_->handles.data(),
                                              static_cast<cudaStream_t>(stream)));
}

}  // namespace glint::cuda
