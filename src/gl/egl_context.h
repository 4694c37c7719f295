#pragma once
// A headless OpenGL 4.5 core context through EGL's device platform: no window, no display server,
// no default framebuffer (surfaceless), so every pass renders into framebuffer objects. The same code
// runs on NVIDIA's driver (GPU machines) and on Mesa's llvmpipe (CPU-only machines and CI).
//
// The context is made current on the constructing thread and stays so until it dies. GL objects
// (gl_objects.h) must be destroyed before it.
#include <optional>
#include <string>

namespace glint {

struct HeadlessGlOptions {
  // EGL device index; nullopt: GLINT_EGL_DEVICE when set, else NVIDIA first, then the first that works.
  std::optional<int> device_index;
  // KHR_debug output (debug-context flag, synchronous callback, see gl_debug_output.h); nullopt:
  // GLINT_GL_DEBUG=0/1 when set, else on in debug builds and off in release builds.
  std::optional<bool> debug_output;
};

class HeadlessGlContext {
public:
  explicit HeadlessGlContext(const HeadlessGlOptions& options = {});
  ~HeadlessGlContext();
  HeadlessGlContext(const HeadlessGlContext&) = delete;
  HeadlessGlContext& operator=(const HeadlessGlContext&) = delete;

  // Makes this context current on the calling thread (after it was used elsewhere).
  void make_current();

  const std::string& renderer() const { return renderer_; }  // GL_RENDERER, e.g. "NVIDIA H100 80GB HBM3/PCIe/SSE2"
  const std::string& vendor() const { return vendor_; }      // GL_VENDOR
  const std::string& version() const { return version_; }    // GL_VERSION, e.g. "4.5 (Core Profile) Mesa 22.3.6"
  int device_index() const { return device_index_; }         // the EGL device in use
  const std::string& device_extensions() const { return device_extensions_; }
  bool debug_output() const { return debug_output_; }
  // One line for logs and `glint info`: "renderer | version | EGL device N".
  std::string description() const;

private:
  void* display_ = nullptr;  // EGLDisplay and EGLContext, kept opaque so that this header needs no EGL
  void* context_ = nullptr;
  int device_index_ = -1;
  bool debug_output_ = false;
  std::string renderer_, vendor_, version_, device_extensions_;
};

// Whether debug output is on for these options (the rule described in HeadlessGlOptions).
bool resolve_gl_debug_output(const HeadlessGlOptions& options);

}  // namespace glint
