#include "gl/egl_context.h"

#include "core/error.h"
#include "core/log.h"
#include "gl/egl_devices.h"
#include "gl/gl_debug_output.h"

#include <dlfcn.h>
#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <fmt/format.h>

#include <cstdlib>
#include <map>
#include <mutex>
#include <string_view>
#include <vector>

// EGL_EXT_device_drm_render_node is newer than libepoxy 1.5.10's generated headers.
#ifndef EGL_DRM_RENDER_NODE_FILE_EXT
#define EGL_DRM_RENDER_NODE_FILE_EXT 0x3377
#endif
#ifndef EGL_CUDA_DEVICE_NV
#define EGL_CUDA_DEVICE_NV 0x323A
#endif

namespace glint {
namespace {

std::string egl_error_name(EGLint code) {
  switch (code) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    default: return fmt::format("EGL error {:#06x}", code);
  }
}

// Device displays are per device and shared by everyone who asks for them, so eglTerminate would
// pull the display from under another HeadlessGlContext on the same device. Count users instead and
// terminate when the last one leaves.
std::mutex g_display_mutex;
std::map<EGLDisplay, int> g_display_users;

void acquire_display(EGLDisplay display) {
  std::lock_guard lock(g_display_mutex);
  ++g_display_users[display];
}

void release_display(EGLDisplay display) {
  std::lock_guard lock(g_display_mutex);
  if (--g_display_users[display] > 0) return;
  g_display_users.erase(display);
  eglTerminate(display);
}

// libepoxy aborts the process when it cannot load libEGL, or the library it resolves desktop GL
// functions from (glvnd's libOpenGL, else libGL); probe first so that a machine without them gets a
// glint::Error (and tests can skip) instead. The handles stay open: epoxy uses these libraries.
void require_gl_libraries() {
  if (dlopen("libEGL.so.1", RTLD_LAZY | RTLD_GLOBAL) == nullptr)
    fail("headless OpenGL needs libEGL.so.1, which could not be loaded: {}", dlerror());
  if (dlopen("libOpenGL.so.0", RTLD_LAZY | RTLD_GLOBAL) == nullptr &&
      dlopen("libGL.so.1", RTLD_LAZY | RTLD_GLOBAL) == nullptr)
    fail("headless OpenGL needs libOpenGL.so.0 or libGL.so.1, neither could be loaded: {}", dlerror());
}

bool has_extension(const char* list, std::string_view name) {
  if (list == nullptr) return false;
  const std::string_view all(list);
  std::size_t at = 0;
  while ((at = all.find(name, at)) != std::string_view::npos) {
    const std::size_t end = at + name.size();
    if ((at == 0 || all[at - 1] == ' ') && (end == all.size() || all[end] == ' ')) return true;
    at = end;
  }
  return false;
}

struct EglDevices {
  std::vector<EGLDeviceEXT> handles;
  std::vector<EglDeviceDescription> descriptions;
};

EglDevices query_egl_devices() {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  // EGL_EXT_device_base is the older bundle of device_enumeration and device_query.
  const bool enumeration =
      has_extension(client, "EGL_EXT_device_enumeration") || has_extension(client, "EGL_EXT_device_base");
  if (!enumeration || !has_extension(client, "EGL_EXT_platform_device"))
    fail("no EGL device: the EGL library lacks EGL_EXT_device_enumeration or EGL_EXT_platform_device "
         "(client extensions: {})",
         client ? client : "none");
  EGLint count = 0;
  if (eglQueryDevicesEXT(0, nullptr, &count) != EGL_TRUE)
    fail("no EGL device: eglQueryDevicesEXT failed ({})", egl_error_name(eglGetError()));
  EglDevices devices;
  devices.handles.resize(static_cast<std::size_t>(count));
  if (count > 0 && eglQueryDevicesEXT(count, devices.handles.data(), &count) != EGL_TRUE)
    fail("no EGL device: eglQueryDevicesEXT failed ({})", egl_error_name(eglGetError()));
  devices.handles.resize(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    EGLDeviceEXT device = devices.handles[static_cast<std::size_t>(i)];
    EglDeviceDescription description;
    description.index = i;
    const char* extensions = eglQueryDeviceStringEXT(device, EGL_EXTENSIONS);
    description.extensions = extensions ? extensions : "";
    if (has_extension(extensions, "EGL_EXT_device_drm_render_node")) {
      if (const char* node = eglQueryDeviceStringEXT(device, EGL_DRM_RENDER_NODE_FILE_EXT)) description.drm_node = node;
    } else if (has_extension(extensions, "EGL_EXT_device_drm")) {
      if (const char* node = eglQueryDeviceStringEXT(device, EGL_DRM_DEVICE_FILE_EXT)) description.drm_node = node;
    }
    EGLAttrib cuda_device = -1;
    if (description.is_nvidia() && eglQueryDeviceAttribEXT(device, EGL_CUDA_DEVICE_NV, &cuda_device) == EGL_TRUE &&
        cuda_device >= 0)
      description.cuda_device = static_cast<int>(cuda_device);
    devices.descriptions.push_back(std::move(description));
  }
  return devices;
}

struct CreatedContext {
  EGLDisplay display;
  EGLContext context;
};

// Initializes the device's display and makes a current OpenGL 4.5 core context on it, or throws
// a glint::Error saying why not (the caller collects these into one message).
CreatedContext create_context_on(EGLDeviceEXT device, bool debug) {
  EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
  if (display == EGL_NO_DISPLAY) fail("eglGetPlatformDisplayEXT failed ({})", egl_error_name(eglGetError()));
  EGLint major = 0, minor = 0;
  if (eglInitialize(display, &major, &minor) != EGL_TRUE)
    fail("eglInitialize failed ({})", egl_error_name(eglGetError()));
  acquire_display(display);
  struct ReleaseOnThrow {
    EGLDisplay display;
    EGLContext context = EGL_NO_CONTEXT;
    bool armed = true;
    ~ReleaseOnThrow() {
      if (!armed) return;
      if (context != EGL_NO_CONTEXT) {
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display, context);
      }
      release_display(display);
    }
  } guard{display};

  if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) fail("eglBindAPI(EGL_OPENGL_API) failed: no desktop OpenGL");
  const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
  if (!has_extension(extensions, "EGL_KHR_surfaceless_context"))
    fail("EGL {}.{} display lacks EGL_KHR_surfaceless_context", major, minor);

  // Configless where possible (Mesa's device platform offers no configs at all); otherwise any
  // config that can render OpenGL, which a surfaceless context never really uses.
  EGLConfig config = EGL_NO_CONFIG_KHR;
  if (!has_extension(extensions, "EGL_KHR_no_config_context")) {
    const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
    EGLint found = 0;
    if (eglChooseConfig(display, wanted, &config, 1, &found) != EGL_TRUE || found < 1)
      fail("no EGL config renders OpenGL and the display lacks EGL_KHR_no_config_context");
  }

  // EGL_CONTEXT_OPENGL_DEBUG is EGL 1.5; without it debug output still works (KHR_debug allows it on
  // any context) but drivers may say less.
  const bool debug_flag = debug && (major > 1 || (major == 1 && minor >= 5));
  std::vector<EGLint> attributes = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                    EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT};
  if (debug_flag) attributes.insert(attributes.end(), {EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE});
  attributes.push_back(EGL_NONE);
  guard.context = eglCreateContext(display, config, EGL_NO_CONTEXT, attributes.data());
  if (guard.context == EGL_NO_CONTEXT)
    fail("eglCreateContext(OpenGL 4.5 core) failed ({})", egl_error_name(eglGetError()));
  if (eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, guard.context) != EGL_TRUE)
    fail("eglMakeCurrent(surfaceless) failed ({})", egl_error_name(eglGetError()));

  GLint gl_major = 0, gl_minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &gl_major);
  glGetIntegerv(GL_MINOR_VERSION, &gl_minor);
  if (gl_major < 4 || (gl_major == 4 && gl_minor < 5))
    fail("got OpenGL {}.{}, need 4.5", gl_major, gl_minor);
  guard.armed = false;
  return {display, guard.context};
}

std::string gl_string(GLenum name) {
  const auto* text = reinterpret_cast<const char*>(glGetString(name));
  return text ? text : "";
}

}  // namespace

std::vector<EglDeviceDescription> list_egl_devices() {
  require_gl_libraries();
  return query_egl_devices().descriptions;
}

bool resolve_gl_debug_output(const HeadlessGlOptions& options) {
  if (options.debug_output) return *options.debug_output;
  if (const char* env = std::getenv("GLINT_GL_DEBUG"); env != nullptr && *env != '\0')
    return std::string_view(env) != "0";
#ifdef NDEBUG
  return false;
#else
  return true;
#endif
}

HeadlessGlContext::HeadlessGlContext(const HeadlessGlOptions& options) {
  require_gl_libraries();
  const EglDevices devices = query_egl_devices();
  if (devices.handles.empty())
    fail("no EGL device found (eglQueryDevicesEXT lists none): install a GPU driver with EGL, or Mesa for llvmpipe");
  debug_output_ = resolve_gl_debug_output(options);

  // An explicit choice is tried alone (falling back would hide a wrong setting); the automatic
  // choice tries every device in order and reports why each failed.
  std::vector<int> order;
  if (options.device_index) {
    if (*options.device_index < 0 || *options.device_index >= static_cast<int>(devices.handles.size()))
      fail("EGL device {} does not exist ({})", *options.device_index, describe_egl_devices(devices.descriptions));
    order = {*options.device_index};
  } else if (const auto env = egl_device_override_from_env()) {
    order = {parse_egl_device_override(*env, devices.descriptions)};
  } else {
    order = egl_device_try_order(devices.descriptions);
  }

  std::vector<std::string> reasons;
  for (const int index : order) {
    const auto& description = devices.descriptions[static_cast<std::size_t>(index)];
    try {
      const CreatedContext created = create_context_on(devices.handles[static_cast<std::size_t>(index)], debug_output_);
      display_ = created.display;
      context_ = created.context;
      device_index_ = index;
      device_extensions_ = description.extensions;
      break;
    } catch (const Error& error) {
      reasons.push_back(fmt::format("device {} ({}): {}", index, description.extensions, error.what()));
    }
  }
  if (context_ == nullptr) {
    if (order.size() == 1 && (options.device_index || egl_device_override_from_env()))
      fail("EGL device {} cannot give OpenGL 4.5 core: {}", order.front(), reasons.front());
    fail("no EGL device supports OpenGL 4.5 core: {}", fmt::join(reasons, "; "));
  }

  renderer_ = gl_string(GL_RENDERER);
  vendor_ = gl_string(GL_VENDOR);
  version_ = gl_string(GL_VERSION);
  // A previous context on this thread may have left a recorded error behind; it is not ours.
  (void)take_gl_debug_error();
  if (debug_output_) install_gl_debug_output();
  log_info("OpenGL: {}", description());
}

HeadlessGlContext::~HeadlessGlContext() {
  if (context_ == nullptr) return;
  if (eglGetCurrentContext() == context_) eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  release_display(display_);
}

void HeadlessGlContext::make_current() {
  if (eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) != EGL_TRUE)
    fail("eglMakeCurrent failed ({})", egl_error_name(eglGetError()));
}

std::string HeadlessGlContext::description() const {
  return fmt::format("{} | {} | EGL device {}{}", renderer_, version_, device_index_, debug_output_ ? " | debug output" : "");
}

}  // namespace glint
