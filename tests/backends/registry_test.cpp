// The backend registry (backends/registry.h): glint's backends are listed once, and a backend
// registered by this test alone appears in the render and bench CLI choices and help, in bench's
// matrix and availability, in the viewer's choices and in make_ray_tracer, with no other edit.
#include "backends/registry.h"

#include "app/bench/backend_availability.h"
#include "app/bench/paper_matrix.h"
#include "app/bench_command.h"
#include "app/render_command.h"
#include "rt/ray_tracer_check.h"
#include "support/error_of.h"
#include "viewer/viewer_settings.h"

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace glint::backends {
namespace {

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// A CPU backend of the test's own: glint's cpu tracer under another name.
Backend fake_backend(std::string name = "fake", std::string missing = "") {
  Backend backend;
  backend.name = std::move(name);
  backend.device = Device::cpu;
  backend.takes_glint_builders = true;
  backend.missing_from_build = std::move(missing);
  backend.help = backend.name + " (a test's backend)";
  backend.make = [] { return make_ray_tracer("cpu"); };
  return backend;
}

// Parses `glint render <arguments>` with the CLI definition of `glint render`; returns CLI11's error.
std::string render_parse_error(const std::vector<std::string>& arguments, RenderOptions& options) {
  CLI::App app;
  add_render_command(app, options);
  std::vector<std::string> argv{"render", "atrium-simple"};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  std::reverse(argv.begin(), argv.end());  // CLI11 takes a reversed vector
  try {
    app.parse(argv);
  } catch (const CLI::ParseError& error) {
    return error.what();
  }
  return "";
}

std::string subcommand_help(void (*add)(CLI::App&, RenderOptions&), const char* name) {
  CLI::App app;
  RenderOptions options;
  add(app, options);
  return app.get_subcommand(name)->help();
}

std::string bench_help() {
  CLI::App app;
  BenchOptions options;
  add_bench_command(app, options);
  return app.get_subcommand("bench")->help();
}

TEST(BackendRegistry, ListsGlintsBackendsOnce) {
  EXPECT_EQ(backend_names(), (std::vector<std::string>{"cpu", "embree", "cuda", "optix", "gl"}));
  EXPECT_TRUE(find_backend("cpu").takes_glint_builders);
  EXPECT_FALSE(find_backend("embree").takes_glint_builders);
  EXPECT_EQ(find_backend("gl").device, Device::gl);
  EXPECT_TRUE(is_gpu_backend("cuda"));
  EXPECT_TRUE(is_gpu_backend("optix"));
  EXPECT_FALSE(is_gpu_backend("gl"));
  EXPECT_FALSE(is_gpu_backend("vulkan"));
  EXPECT_EQ(builder_backends_text(), "cpu, cuda and gl");
  EXPECT_EQ(gpu_backends_text(), "cuda or optix");
  EXPECT_EQ(find_backend("optix").built(), GLINT_HAVE_OPTIX != 0);
  EXPECT_EQ(find_backend("cuda").built(), GLINT_HAVE_CUDA != 0);
  const std::string unknown = testing::error_of([] { (void)find_backend("vulkan"); });
  EXPECT_NE(unknown.find("unknown ray tracing backend \"vulkan\" (known: cpu, embree, cuda, optix, gl)"),
            std::string::npos)
      << unknown;
}

TEST(BackendRegistry, EveryBackendIsInTheHelpOfRenderAndBench) {
  const std::string render = subcommand_help(add_render_command, "render");
  const std::string bench = bench_help();
  for (const Backend& backend : all_backends()) {
    EXPECT_NE(render.find(backend.help), std::string::npos) << backend.name << "\n" << render;
    EXPECT_NE(bench.find(backend.name), std::string::npos) << backend.name;
    for (const std::string& structure : backend.structures)
      EXPECT_NE(render.find(structure), std::string::npos) << structure;
  }
}

TEST(BackendRegistry, ATestsBackendAppearsInTheCliChoicesAndTheBenchMatrix) {
  {
    RenderOptions options;
    EXPECT_NE(render_parse_error({"--backend", "fake"}, options), "") << "not registered yet";
  }
  {
    const ScopedBackendRegistration registration(fake_backend());
    EXPECT_TRUE(contains(backend_names(), "fake"));

    // glint render: a choice of --backend, in its help, and a pipeline setting.
    RenderOptions options;
    EXPECT_EQ(render_parse_error({"--backend", "fake", "--accel", "lbvh"}, options), "");
    EXPECT_EQ(options.backend, "fake");
    EXPECT_NE(subcommand_help(add_render_command, "render").find("fake (a test's backend)"), std::string::npos);
    const render::FramePipelineSettings settings = render_pipeline_settings(options);
    EXPECT_EQ(settings.ray_tracing.backend, "fake");
    EXPECT_EQ(settings.ray_tracing.accel.builder, accel::BvhBuilder::lbvh);
    EXPECT_EQ(builder_backends_text(), "cpu, cuda, gl and fake");

    // glint bench: listed, available, and in the matrix with glint's builders.
    EXPECT_NE(bench_help().find("fake"), std::string::npos);
    EXPECT_EQ(glint::parse_name_list("--backends", "cpu,fake", backend_names()),
              (std::vector<std::string>{"cpu", "fake"}));
    EXPECT_FALSE(bench::backend_unavailable_reason("fake").has_value());
    bench::MatrixOptions matrix;
    matrix.structures = bench::structures_of({"cpu", "fake"}, {"sah", "lbvh"});
    std::vector<std::string> labels;
    for (const bench::Structure& structure : matrix.structures) labels.push_back(structure.label());
    EXPECT_EQ(labels, (std::vector<std::string>{"cpu-sah", "cpu-lbvh", "fake-sah", "fake-lbvh"}));
    int fake_cells = 0;
    for (const bench::Cell& cell : bench::paper_matrix(matrix))
      if (cell.structure.backend == "fake" && !cell.skip_reason) ++fake_cells;
    EXPECT_GT(fake_cells, 0);

    // The viewer's choices, and the factory.
    EXPECT_TRUE(contains(viewer::available_backends(), "fake"));
    const std::unique_ptr<rt::RayTracer> tracer = make_ray_tracer("fake");
    const Scene scene = testing::make_instanced_scene();
    tracer->build(scene, {});
    const std::vector<accel::Ray> rays = testing::random_rays(scene, 200, 3);
    EXPECT_EQ(testing::compare_hits(scene, rays, testing::brute_force_hits(scene, rays), testing::trace(*tracer, rays)),
              "");

    const std::string twice = testing::error_of([] { const ScopedBackendRegistration again(fake_backend()); });
    EXPECT_NE(twice.find("already taken"), std::string::npos) << twice;
  }
  EXPECT_FALSE(contains(backend_names(), "fake")) << "gone with its registration";
  RenderOptions options;
  EXPECT_NE(render_parse_error({"--backend", "fake"}, options), "");
}

TEST(BackendRegistry, ABackendThisBinaryLacksSaysWhyEverywhere) {
  const ScopedBackendRegistration registration(fake_backend("absent", "glint was built without absent (configure with -DABSENT=ON)"));
  const std::string built = testing::error_of([] { check_backend_built("absent"); });
  EXPECT_EQ(built, "the absent backend is not in this build: glint was built without absent (configure with -DABSENT=ON)");
  EXPECT_EQ(testing::error_of([] { (void)make_ray_tracer("absent"); }), built);
  EXPECT_EQ(bench::backend_unavailable_reason("absent"),
            "not in this build: glint was built without absent (configure with -DABSENT=ON)");
  EXPECT_FALSE(contains(viewer::available_backends(), "absent"));
}

TEST(BackendRegistry, OwnStructuresAreCheckedAgainstTheirBackend) {
  RenderOptions options;
  options.backend = "embree";
  options.accel = "lbvh";
  EXPECT_NE(testing::error_of([&] { (void)render_pipeline_settings(options); })
                .find("--accel lbvh applies to the cpu, cuda and gl backends; the embree backend builds its own"),
            std::string::npos);
  options.backend = "cpu";
  options.accel = "optix-fastbuild";
  EXPECT_NE(testing::error_of([&] { (void)render_pipeline_settings(options); })
                .find("--accel optix-fastbuild is a structure of the optix backend: it needs --backend optix"),
            std::string::npos);
  options.backend = "optix";
  EXPECT_EQ(render_pipeline_settings(options).ray_tracing.accel.backend_structure, "optix-fastbuild");
  options.accel = "sah";  // the default: the backend's own default structure
  EXPECT_EQ(render_pipeline_settings(options).ray_tracing.accel.backend_structure, "");
  options.accel = "lbvh";
  EXPECT_NE(testing::error_of([&] { (void)render_pipeline_settings(options); })
                .find("the optix backend takes optix-fasttrace or optix-fastbuild"),
            std::string::npos);
}

}  // namespace
}  // namespace glint::backends
