#include "backends/registry.h"

#include "core/error.h"
#include "cuda/cuda_ray_tracer.h"
#include "cuda/device_query.h"
#include "gl_rt/make_gl_ray_tracer.h"
#include "optix/build_preference.h"
#include "rt/cpu_ray_tracer.h"
#include "rt/embree_ray_tracer.h"
#if GLINT_HAVE_OPTIX
#include "optix/backend.h"
#endif

#include <algorithm>
#include <utility>

namespace glint::backends {
namespace {

// glint's own backends: the one place that names them.
std::vector<Backend> built_in_backends() {
  std::vector<Backend> list;
  list.push_back({"cpu", Device::cpu, true, {}, "", "cpu (glint's own structures on the CPU)",
                  [] { return std::unique_ptr<rt::RayTracer>(std::make_unique<rt::CpuRayTracer>()); }});
  list.push_back({"embree", Device::cpu, false, {}, "", "embree (Intel Embree 3's structures on the CPU)",
                  [] { return std::unique_ptr<rt::RayTracer>(std::make_unique<rt::EmbreeRayTracer>()); }});
  list.push_back({"cuda", Device::cuda, true, {},
                  GLINT_HAVE_CUDA ? ""
                                  : "glint was built without CUDA (configure with GLINT_CUDA=ON and nvcc on the PATH)",
                  "cuda (glint's own structures on the GPU; needs a CUDA GPU)",
                  [] { return cuda::make_cuda_ray_tracer(); }});
  list.push_back({"optix", Device::cuda, false, optix::kBuildPreferenceNames.names(),
                  GLINT_HAVE_OPTIX ? ""
                                   : "glint was built without OptiX (configure with -DOptiX_INSTALL_DIR=<OptiX SDK "
                                     "folder> and CUDA on; docs/optix.md)",
                  "optix (NVIDIA OptiX's; needs a build with OptiX, docs/optix.md)",
                  []() -> std::unique_ptr<rt::RayTracer> {
#if GLINT_HAVE_OPTIX
                    return std::make_unique<optix::OptixRayTracer>();
#else
                    fail("the optix backend is not in this build");  // not reached: missing_from_build is set
#endif
                  }});
  list.push_back({"gl", Device::gl, true, {}, "",
                  "gl (glint's own structures traced in OpenGL compute shaders, built on the CPU)",
                  [] { return gl_rt::make_gl_ray_tracer(); }});
  return list;
}

std::vector<Backend>& registry() {
  static std::vector<Backend> backends = built_in_backends();
  return backends;
}

// "a, b and c" / "a, b or c".
std::string listed(const std::vector<std::string>& names, std::string_view last_joint) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) text += i + 1 == names.size() ? fmt::format(" {} ", last_joint) : std::string(", ");
    text += names[i];
  }
  return text;
}

std::vector<std::string> names_where(bool (*keep)(const Backend&)) {
  std::vector<std::string> names;
  for (const Backend& backend : registry())
    if (keep(backend)) names.push_back(backend.name);
  return names;
}

}  // namespace

const std::vector<Backend>& all_backends() { return registry(); }

std::vector<std::string> backend_names() {
  return names_where([](const Backend&) { return true; });
}

const Backend* backend_if_known(std::string_view name) {
  for (const Backend& backend : registry())
    if (backend.name == name) return &backend;
  return nullptr;
}

const Backend& find_backend(std::string_view name) {
  if (const Backend* backend = backend_if_known(name)) return *backend;
  std::string known;
  for (const std::string& known_name : backend_names()) known += (known.empty() ? "" : ", ") + known_name;
  fail("unknown ray tracing backend \"{}\" (known: {})", name, known);
}

void check_backend_built(std::string_view name) {
  const Backend& backend = find_backend(name);
  if (!backend.built()) fail("the {} backend is not in this build: {}", backend.name, backend.missing_from_build);
}

void check_backend_runnable(std::string_view name, std::string_view request) {
  check_backend_built(name);
  if (!is_gpu_backend(name)) return;
  const std::string what = request.empty() ? "--backend " + std::string(name) : std::string(request);
  require_cuda_gpu(what.c_str());
}

std::unique_ptr<rt::RayTracer> make_ray_tracer(std::string_view name) {
  check_backend_built(name);
  return find_backend(name).make();
}

bool is_gpu_backend(std::string_view name) {
  const Backend* backend = backend_if_known(name);
  return backend != nullptr && backend->device == Device::cuda;
}

const Backend* structure_owner(std::string_view structure) {
  for (const Backend& backend : registry())
    if (std::find(backend.structures.begin(), backend.structures.end(), structure) != backend.structures.end())
      return &backend;
  return nullptr;
}

std::string backends_help() {
  std::vector<std::string> entries;
  for (const Backend& backend : registry()) entries.push_back(backend.help.empty() ? backend.name : backend.help);
  return listed(entries, "or");
}

std::string builder_backends_text() {
  return listed(names_where([](const Backend& backend) { return backend.takes_glint_builders; }), "and");
}

std::string gpu_backends_text() {
  return listed(names_where([](const Backend& backend) { return backend.device == Device::cuda; }), "or");
}

ScopedBackendRegistration::ScopedBackendRegistration(Backend backend) : name_(backend.name) {
  if (name_.empty() || backend_if_known(name_) != nullptr)
    fail("backend registration: the name \"{}\" is empty or already taken", name_);
  if (!backend.make) fail("backend registration: \"{}\" has no factory", name_);
  registry().push_back(std::move(backend));
}

ScopedBackendRegistration::~ScopedBackendRegistration() {
  std::vector<Backend>& backends = registry();
  backends.erase(std::remove_if(backends.begin(), backends.end(),
                                [&](const Backend& backend) { return backend.name == name_; }),
                 backends.end());
}

}  // namespace glint::backends
