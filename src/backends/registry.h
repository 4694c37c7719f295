#pragma once
// The ray-tracing backends glint knows, in one table: per backend its name, where it traces (CPU,
// CUDA or GL), whether it takes glint's builders (--accel), its own structures, whether this binary
// has it and why not, its help text and its factory. Everything that lists or checks backends reads
// it: the CLI's --backend choices and help (render, bench, view), run.json, bench's matrix and
// availability, the Python module. Adding a backend is one entry in registry.cpp (docs/ray-tracer.md,
// "Adding a backend"); a test registers one of its own with ScopedBackendRegistration.
//
// Layering: this folder sits above rt/ (the RayTracer interface and the cpu and embree backends),
// cuda/, optix/ and gl_rt/, which know nothing of each other's backends; render/ and app/ sit above it.
#include "core/enum_names.h"
#include "rt/ray_tracer.h"

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace glint::backends {

// Where a backend's structures live, and so how the renderer hands it rays.
enum class Device {
  cpu,   // host memory: the ray list is read back and traced by RayTracer::trace_closest (TBB)
  cuda,  // a CUDA GPU: rays stay in GL buffers mapped into CUDA (rt::DeviceTracing); needs a CUDA GPU,
         // and its structures follow the GPU deformer in place
  gl,    // the GL context's GPU: OpenGL compute shaders over the renderer's buffers (rt::GlTracing);
         // made on the current GL 4.5 context
};

inline constexpr EnumNames<Device, 3> kDeviceNames{
    "backend device", {{Device::cpu, "cpu"}, {Device::cuda, "cuda"}, {Device::gl, "gl"}}};

struct Backend {
  std::string name;  // --backend, run.json's "backend", RayTracer::name()
  Device device = Device::cpu;
  // --accel picks its per-mesh structure from glint's builders (the cpu, cuda and gl backends);
  // otherwise it builds its own structures.
  bool takes_glint_builders = false;
  // The structures of its own it offers, by --accel name (rt::AccelOptions::backend_structure), its
  // default first: optix-fasttrace, optix-fastbuild. Empty with glint's builders or a single
  // structure (embree).
  std::vector<std::string> structures;
  // Empty when this binary has the backend; otherwise one line saying why not and how to build it
  // in ("glint was built without OptiX (configure with -DOptiX_INSTALL_DIR=...)").
  std::string missing_from_build;
  // Its entry in --backend's help: "cuda (glint's own structures on the GPU; needs a CUDA GPU)".
  std::string help;
  // Makes one; glint::Error for what the machine lacks (no CUDA GPU, no OpenGL 4.5 context). Not
  // called when missing_from_build is set.
  std::function<std::unique_ptr<rt::RayTracer>()> make;

  bool built() const { return missing_from_build.empty(); }
};

// Every backend in the order lists give them: glint's own (cpu, embree, cuda, optix, gl), then any a
// test registered. The reference is valid until the next registration change.
const std::vector<Backend>& all_backends();
// Their names: the choices of --backend (a CLI11 IsMember check) and of bench's --backends.
std::vector<std::string> backend_names();
// The backend named `name`, or null.
const Backend* backend_if_known(std::string_view name);
// The backend named `name`; glint::Error `unknown ray tracing backend "<name>" (known: ...)` otherwise.
const Backend& find_backend(std::string_view name);

// glint::Error, one line saying how to build it in, for a backend this binary lacks (optix without
// OptiX, cuda without CUDA), or the unknown-name error; nothing otherwise. Lets a command refuse
// before it writes anything.
void check_backend_built(std::string_view name);
// check_backend_built, then, for a Device::cuda backend (cuda, optix), "<request> needs a CUDA GPU:
// <why>" when this machine has no usable one: whether `name` can run here, checked before a command
// (render, the Python module, the viewer's settings) builds or writes anything. `request` names what
// asked for it in the caller's terms; empty: "--backend <name>".
void check_backend_runnable(std::string_view name, std::string_view request = {});
// A new tracer of backend `name`: check_backend_built, then its factory.
std::unique_ptr<rt::RayTracer> make_ray_tracer(std::string_view name);
// True for the backends that trace on a CUDA GPU through rt::DeviceTracing (Device::cuda: cuda,
// optix): they need a CUDA GPU, trace the GL-shared ray list in place and follow the GPU deformer.
// False for unknown names.
bool is_gpu_backend(std::string_view name);
// The backend offering `structure` as one of its own (optix for "optix-fastbuild"), or null.
const Backend* structure_owner(std::string_view structure);

// Help texts built from the table: "cpu (...), embree (...), ... or gl (...)"; the names of the
// backends that take glint's builders ("cpu, cuda and gl"); those of Device::cuda ("cuda or optix").
std::string backends_help();
std::string builder_backends_text();
std::string gpu_backends_text();

// Registers `backend` (a name not yet known, a factory) for this object's lifetime: a test's own
// backend appears in every list above, the CLI choices and bench's matrix, with no other edit.
// Not thread-safe: register before the lists are read (tests do it on their main thread).
class ScopedBackendRegistration {
public:
  explicit ScopedBackendRegistration(Backend backend);
  ~ScopedBackendRegistration();
  ScopedBackendRegistration(const ScopedBackendRegistration&) = delete;
  ScopedBackendRegistration& operator=(const ScopedBackendRegistration&) = delete;

private:
  std::string name_;
};

}  // namespace glint::backends
