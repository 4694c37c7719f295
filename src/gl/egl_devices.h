#pragma once
// EGL devices (EGL_EXT_device_enumeration) and the order glint tries them in: NVIDIA's devices
// first (they advertise EGL_NV_device_cuda, which CUDA-GL interop needs), then the rest by index
// (Mesa's llvmpipe on machines without a GPU). GLINT_EGL_DEVICE=<index> picks one explicitly.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

struct EglDeviceDescription {
  int index = 0;
  std::string extensions;  // eglQueryDeviceStringEXT(EGL_EXTENSIONS)
  std::string drm_node;    // DRM render node or device file when the device has one, else empty
  // The CUDA device ordinal of an NVIDIA device (EGL_NV_device_cuda's EGL_CUDA_DEVICE_NV), else
  // nullopt: how a process driving one GPU of several pairs its EGL and CUDA devices (app/mpi/).
  std::optional<int> cuda_device = std::nullopt;
  bool is_nvidia() const { return extensions.find("EGL_NV_device_cuda") != std::string::npos; }
};

// Indices in the order glint tries them: NVIDIA devices first, then the others, each by index.
std::vector<int> egl_device_try_order(const std::vector<EglDeviceDescription>& devices);

// "device 0: EGL_MESA_device_software EGL_EXT_device_drm_render_node; device 1: ..."
std::string describe_egl_devices(const std::vector<EglDeviceDescription>& devices);

// The device index named by the text of GLINT_EGL_DEVICE; anything but an index of `devices` is a
// glint::Error listing the devices.
int parse_egl_device_override(std::string_view text, const std::vector<EglDeviceDescription>& devices);

// Every EGL device of this machine, described (no context is made); a glint::Error when EGL or its
// device enumeration is missing. Defined in egl_context.cpp, which loads EGL.
std::vector<EglDeviceDescription> list_egl_devices();

// The GLINT_EGL_DEVICE environment variable, or nullopt when unset or empty.
std::optional<std::string> egl_device_override_from_env();

}  // namespace glint
