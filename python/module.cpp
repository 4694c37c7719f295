// The Python module `glint` (docs/python.md): glint.Structure over numpy triangles (any builder of
// the menu, any ray tracing backend), closest-hit and occlusion queries, refit, stats; glint.render,
// one frame of `glint render` as a numpy image. Every glint::Error becomes glint.Error with glint's
// one-line message. Long calls (builds, traces, refits, renders) release the GIL.
#include "accel/builders/builder.h"
#include "rt/blas_structure.h"
#include "app/render_frame_api.h"
#include "core/error.h"
#include "cuda/device_query.h"
#include "python/mesh_structure.h"
#include "python/numpy_input.h"
#include "rt/ray_tracer.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace py = pybind11;

namespace glint::python {
namespace {

std::unique_ptr<MeshStructure> make_structure(const py::object& vertices, const py::object& indices,
                                              const std::string& builder, const std::string& backend) {
  std::vector<vec3> positions = points_from_array(vertices, "glint.Structure: vertices");
  std::vector<uint32_t> triangles = indices_from_array(indices, positions.size(), "glint.Structure: indices");
  py::gil_scoped_release unlocked;
  return std::make_unique<MeshStructure>(std::move(positions), std::move(triangles), builder, backend);
}

// {"t", "prim", "u", "v"}: float32, int64 (-1 for a miss; t is then inf), float32, float32.
py::dict trace_closest(const MeshStructure& structure, const py::object& origins, const py::object& directions,
                       const py::object& t_min, const py::object& t_max) {
  const std::vector<accel::Ray> rays =
      rays_from_arrays(origins, directions, t_min, t_max, "glint.Structure.trace_closest");
  std::vector<accel::Hit> hits(rays.size());
  {
    py::gil_scoped_release unlocked;
    structure.trace_closest(rays, hits);
  }
  const auto n = static_cast<py::ssize_t>(hits.size());
  py::array_t<float> t(n), u(n), v(n);
  py::array_t<int64_t> prim(n);
  float* t_out = t.mutable_data();
  float* u_out = u.mutable_data();
  float* v_out = v.mutable_data();
  int64_t* prim_out = prim.mutable_data();
  for (std::size_t i = 0; i < hits.size(); ++i) {
    t_out[i] = hits[i].t;
    prim_out[i] = hits[i].valid() ? static_cast<int64_t>(hits[i].prim) : -1;
    u_out[i] = hits[i].u;
    v_out[i] = hits[i].v;
  }
  py::dict result;
  result["t"] = t;
  result["prim"] = prim;
  result["u"] = u;
  result["v"] = v;
  return result;
}

py::array_t<bool> trace_any(const MeshStructure& structure, const py::object& origins, const py::object& directions,
                            const py::object& t_min, const py::object& t_max) {
  const std::vector<accel::Ray> rays = rays_from_arrays(origins, directions, t_min, t_max, "glint.Structure.trace_any");
  std::vector<uint8_t> occluded(rays.size());
  {
    py::gil_scoped_release unlocked;
    structure.trace_any(rays, occluded);
  }
  py::array_t<bool> result(static_cast<py::ssize_t>(occluded.size()));
  bool* out = result.mutable_data();
  for (std::size_t i = 0; i < occluded.size(); ++i) out[i] = occluded[i] != 0;
  return result;
}

void refit(MeshStructure& structure, const py::object& vertices, const std::string& policy) {
  std::vector<vec3> positions = points_from_array(vertices, "glint.Structure.refit: vertices");
  const rt::UpdatePolicy update = rt::parse_update_policy(policy);
  py::gil_scoped_release unlocked;
  structure.update(std::move(positions), update);
}

py::dict stats(const MeshStructure& structure) {
  const rt::RayTracerStats stats = structure.stats();
  py::dict result;
  result["backend"] = structure.backend();
  result["builder"] = structure.builder();
  result["vertices"] = structure.vertex_count();
  result["triangles"] = structure.triangle_count();
  result["build_ms"] = stats.build_ms;
  result["last_update_ms"] = stats.last_update_ms;
  result["memory_bytes"] = stats.memory_bytes;
  result["rebuilds"] = stats.rebuilds;
  result["refits"] = stats.refits;
  result["sah_drift"] = stats.blas_sah_drift ? py::cast(*stats.blas_sah_drift) : py::none();
  return result;
}

py::array_t<uint8_t> render_scene_frame(const std::string& scene, int frame, int width, int height,
                                        const std::string& reflections, const std::string& backend,
                                        const std::string& accel, const std::string& update,
                                        const std::string& shadows, const std::string& gbuffer, bool deform) {
  RenderOptions options;
  options.scene = scene;
  options.width = width;
  options.height = height;
  options.reflections = reflections;
  options.backend = backend;
  options.accel = accel;
  options.update = update;
  options.shadows = shadows;
  options.gbuffer = gbuffer;
  options.deform = deform ? "on" : "off";
  ImageRgba8 image;
  {
    py::gil_scoped_release unlocked;
    image = render_frame(options, frame);
  }
  py::array_t<uint8_t> result({static_cast<py::ssize_t>(image.height), static_cast<py::ssize_t>(image.width),
                               py::ssize_t{4}});
  std::memcpy(result.mutable_data(), image.pixels.data(), image.pixels.size() * sizeof(image.pixels[0]));
  return result;
}

}  // namespace
}  // namespace glint::python

PYBIND11_MODULE(glint, m) {
  using namespace glint;
  using namespace glint::python;
  m.doc() = "glint: acceleration structures and ray tracing over numpy triangles, and frames of glint's "
            "hybrid reflection renderer (docs/python.md)";
  m.attr("__version__") = GLINT_VERSION;

  py::register_exception<Error>(m, "Error", PyExc_RuntimeError).doc() =
      "A failure glint reports: its one-line message says what and where (the argument or file).";

  // The --accel menu: every builder's BVH, then the SAH kd-tree (rt/blas_structure.h).
  py::list builders;
  for (const std::string& name : rt::blas_structure_names()) builders.append(name);
  m.attr("BUILDERS") = py::tuple(builders);
  py::list backends;
  for (const char* backend : kStructureBackends) backends.append(backend);
  m.attr("BACKENDS") = py::tuple(backends);
  m.def("cuda_available", &cuda_gpu_present,
        "True when glint was built with CUDA and a CUDA GPU is usable now (the cuda and optix backends need one).");

  const RenderOptions defaults;
  py::class_<MeshStructure>(m, "Structure",
                            "An acceleration structure over one triangle mesh, built by a ray tracing backend.")
      .def(py::init(&make_structure), py::arg("vertices"), py::arg("indices"), py::arg("builder") = defaults.accel,
           py::arg("backend") = "cpu",
           "vertices: float32/float64 (N, 3) array-like; indices: integer (M, 3) vertex numbers; builder: one of "
           "BUILDERS (cpu and cuda backends); backend: one of BACKENDS (cuda and optix need a CUDA GPU).")
      .def("trace_closest", &trace_closest, py::arg("origins"), py::arg("directions"), py::arg("t_min") = 0.0,
           py::arg("t_max") = std::numeric_limits<double>::infinity(),
           "Closest hit of each ray origin + t * direction with t in [t_min, t_max]: a dict of arrays t (float32, "
           "inf on a miss), prim (int64 triangle number, -1 on a miss), u, v (float32 barycentrics: the point is "
           "(1 - u - v) v0 + u v1 + v v2).")
      .def("trace_any", &trace_any, py::arg("origins"), py::arg("directions"), py::arg("t_min") = 0.0,
           py::arg("t_max") = std::numeric_limits<double>::infinity(),
           "Occlusion: a bool array, True where the ray hits any triangle with t in [t_min, t_max].")
      .def("refit", &refit, py::arg("vertices"), py::arg("policy") = "refit",
           "The vertices moved (same count, same triangles): refit the structure (policy 'refit'), rebuild it "
           "('rebuild') or refit and rebuild when its SAH cost grew 30 % ('auto').")
      .def("stats", &stats, "backend, builder, vertices, triangles, build_ms, last_update_ms, memory_bytes, rebuilds, "
                            "refits, sah_drift (None when the backend cannot measure it).")
      .def_property_readonly("builder", &MeshStructure::builder)
      .def_property_readonly("backend", &MeshStructure::backend)
      .def_property_readonly("vertex_count", &MeshStructure::vertex_count)
      .def_property_readonly("triangle_count", &MeshStructure::triangle_count);

  m.def("render", &render_scene_frame, py::arg("scene") = defaults.scene, py::arg("frame") = 0,
        py::arg("width") = defaults.width, py::arg("height") = defaults.height,
        py::arg("reflections") = defaults.reflections, py::arg("backend") = defaults.backend,
        py::arg("accel") = defaults.accel, py::arg("update") = defaults.update,
        py::arg("shadows") = defaults.shadows, py::arg("gbuffer") = defaults.gbuffer, py::arg("deform") = true,
        "One frame of the scene's walkthrough as `glint render --frames FRAME` renders it (same options, same "
        "pixels): a uint8 array (height, width, 4), RGBA, top row first.");
}
