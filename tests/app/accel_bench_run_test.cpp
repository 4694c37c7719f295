// accel-bench end to end: in process on a scene built in code, and through the CLI.
#include "accel/builders/builder.h"
#include "app/accel_bench/bench_run.h"
#include "app/accel_bench/candidates.h"
#include "app/accel_bench/hit_check.h"
#include "app/accel_bench/report_json.h"
#include "app/accel_bench/report_table.h"
#include "app/accel_bench_command.h"
#include "app/cli_runner.h"
#include "cuda/device_query.h"
#include "rt/tiny_scene.h"
#include "support/error_of.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>

#include <unistd.h>

namespace glint::accel_bench {
namespace {

// Binary BVHs report an SAH cost; the kd-tree, wide BVHs and Embree do not (docs/accel-bench.md).
bool is_binary_bvh(const std::string& name) {
  for (const accel::BvhBuilder builder : accel::kAllBvhBuilders)
    if (accel::builder_name(builder) == name) return true;
  return false;
}

BenchOptions small_options() {
  BenchOptions options;
  options.structures = parse_structure_list("all");  // the CPU structures and Embree
  options.rays = RayKind::reflection;
  options.frames = {0, 50, 99};
  options.width = 48;
  options.height = 32;
  options.deform_frames = 4;
  options.timed_runs = 1;
  return options;
}

TEST(AccelBenchRun, EveryStructureIsBuiltCheckedTimedAndDeformed) {
  Scene scene = glint::testing::make_tiny_scene(16);
  std::vector<std::string> progress;
  BenchOptions options = small_options();
  options.progress = [&](const std::string& line) { progress.push_back(line); };
  const BenchReport report = run_accel_bench(scene, options);

  EXPECT_EQ(report.reference, "none");  // brute force is cheap here, so it is the reference
  EXPECT_GT(report.ray_count, 100u);
  EXPECT_GT(report.ray_hits, 0u);
  EXPECT_EQ(report.scene_triangles, 4u + 2u * 16u * 16u * 2u);
  ASSERT_EQ(report.structures.size(), options.structures.size());
  for (size_t i = 0; i < report.structures.size(); ++i) {
    const StructureResult& r = report.structures[i];
    EXPECT_EQ(r.name, options.structures[i]);
    EXPECT_TRUE(r.skipped.empty()) << r.name;
    ASSERT_TRUE(r.mrays_per_s) << r.name;
    EXPECT_GT(*r.mrays_per_s, 0.0) << r.name;
    ASSERT_TRUE(r.ratio_to_embree_medium) << r.name;
    EXPECT_GT(r.memory_bytes, 0u) << r.name;
    const bool embree = r.name.rfind("embree-", 0) == 0;
    EXPECT_EQ(r.nodes.has_value(), !embree) << r.name;
    // build_ms is the median of build_runs builds (3 by default), the first one kept beside it.
    EXPECT_GT(r.first_build_ms, 0.0) << r.name;
    EXPECT_GT(r.build_ms, 0.0) << r.name;
    EXPECT_NEAR(r.mprims_per_s, static_cast<double>(report.scene_triangles) / (r.build_ms * 1e3), 1e-9 * r.mprims_per_s)
        << r.name;
    EXPECT_EQ(r.sah.has_value(), is_binary_bvh(r.name)) << r.name;
  }
  const auto medium = std::find_if(report.structures.begin(), report.structures.end(),
                                   [](const StructureResult& r) { return r.name == "embree-medium"; });
  ASSERT_NE(medium, report.structures.end());
  EXPECT_DOUBLE_EQ(*medium->ratio_to_embree_medium, 1.0);
  // SAH of a real BVH beats one leaf of everything.
  const auto sah = std::find_if(report.structures.begin(), report.structures.end(),
                                [](const StructureResult& r) { return r.name == "sah"; });
  EXPECT_LT(*sah->sah, *report.structures[0].sah);

  EXPECT_EQ(report.deformable_meshes, std::vector<std::string>{"sheet"});
  EXPECT_EQ(report.deformable_triangles, 2u * 16u * 16u * 2u);
  ASSERT_EQ(report.deform.size(), options.structures.size());
  for (const DeformResult& d : report.deform) {
    // Spatial splits (sbvh) make a structure non-refittable; Embree refits only at quality "refit"
    // and exposes no SAH.
    const bool own = d.name.rfind("embree-", 0) != 0;
    const bool refits = (own && d.name != "sbvh" && d.name != "kdtree") || d.name == "embree-refit";
    EXPECT_EQ(d.refit_ms.has_value(), refits) << d.name;
    const bool has_sah = is_binary_bvh(d.name) && d.name != "sbvh";
    ASSERT_EQ(d.sah_drift.has_value(), has_sah) << d.name;
    // Small waves: the refitted tree stays close to a fresh one.
    if (has_sah) {
      EXPECT_NEAR(*d.sah_drift, 1.0, 0.5) << d.name;
    }
  }
  // One progress line per structure (static and deformation) plus the ray and deformation lines.
  EXPECT_EQ(progress.size(), 3 * options.structures.size() + 2);

  const std::string table = format_report_table(report);
  for (const std::string& name : options.structures) EXPECT_NE(table.find(name), std::string::npos);
  EXPECT_NE(table.find("SAH drift"), std::string::npos);
}

TEST(AccelBenchRun, AMismatchIsCountedNamingTheStructureAndRayAndTheRunGoesOn) {
  Scene scene = glint::testing::make_tiny_scene(4);
  BenchOptions options = small_options();
  options.structures = {"sah", "embree-medium", "embree-high"};
  options.deform_frames = 0;
  options.tamper_hits = [](const std::string& name, std::span<accel::Hit> hits) {
    if (name == "embree-medium") hits[3].t *= 1.01f;
  };
  const BenchReport report = run_accel_bench(scene, options);
  ASSERT_EQ(report.structures.size(), 3u);
  EXPECT_EQ(report.structures[1].disagreements, 1u);
  EXPECT_NE(report.structures[1].hit_problem.find("embree-medium disagrees with sah on 1 of"), std::string::npos)
      << report.structures[1].hit_problem;
  EXPECT_NE(report.structures[1].hit_problem.find("first: ray 3 "), std::string::npos) << report.structures[1].hit_problem;
  EXPECT_TRUE(report.structures[2].mrays_per_s.has_value()) << "the structures after it are still measured";
  EXPECT_EQ(report.structures[2].disagreements, 0u);
  EXPECT_EQ(hit_problems(report), std::vector<std::string>{report.structures[1].hit_problem});
}

TEST(AccelBenchRun, BadOptionsAreClearErrors) {
  Scene scene = glint::testing::make_tiny_scene(4);
  BenchOptions options = small_options();
  options.frames = {100};
  EXPECT_NE(glint::testing::error_of([&] { (void)run_accel_bench(scene, options); }).find("frame 100 is outside"),
            std::string::npos);
  options = small_options();
  options.structures = {"sah", "kd-magic"};
  EXPECT_NE(glint::testing::error_of([&] { (void)run_accel_bench(scene, options); }).find("unknown structure \"kd-magic\""),
            std::string::npos);
  EXPECT_THROW((void)parse_structure_list("sah,,median"), Error);
  EXPECT_THROW((void)parse_frame_list("1,-2"), Error);
  EXPECT_THROW((void)parse_frame_list("12x"), Error);
  EXPECT_EQ(parse_frame_list("0,7,4400"), (std::vector<int>{0, 7, 4400}));
  // Embree's qualities are always added, after the named ones, without duplicates.
  EXPECT_EQ(parse_structure_list("sah,embree-high"),
            (std::vector<std::string>{"sah", "embree-high", "embree-low", "embree-medium", "embree-refit"}));
}

TEST(AccelBenchRun, AllMeansTheBackendsStructuresPlusEmbree) {
  const std::vector<std::string> cpu = parse_structure_list("all");
  const std::vector<std::string> cuda = parse_structure_list("all", "cuda");
  EXPECT_NE(std::find(cpu.begin(), cpu.end(), "sah-wide8"), cpu.end());
  EXPECT_EQ(std::count_if(cpu.begin(), cpu.end(), [](const std::string& n) { return n.starts_with("cuda-"); }), 0);
  EXPECT_EQ(cuda, (std::vector<std::string>{"cuda-none", "cuda-median", "cuda-sah", "cuda-sbvh", "cuda-lbvh",
                                            "cuda-trbvh", "cuda-ploc", "cuda-kdtree", "cuda-lbvh-persistent",
                                            "cuda-sah-persistent", "embree-low", "embree-medium", "embree-high",
                                            "embree-refit"}));
  // Named structures of both kinds mix.
  EXPECT_EQ(parse_structure_list("cuda-lbvh,sah-wide8", "cuda").front(), "cuda-lbvh");
  EXPECT_EQ(parse_structure_list("all", "optix"),
            (std::vector<std::string>{"optix-fasttrace", "optix-fastbuild", "embree-low", "embree-medium", "embree-high",
                                      "embree-refit"}));
  EXPECT_THROW((void)parse_structure_list("all", "vulkan"), Error);
}

// The GPU rows: every structure's hits are checked against the CPU reference before timing, and
// the GPU ones report GPU times and SAH like the CPU ones.
TEST(AccelBenchRun, CudaStructuresAgreeWithTheCpuReference) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  Scene scene = glint::testing::make_tiny_scene(4);
  BenchOptions options = small_options();
  options.structures = {"sah",         "cuda-lbvh",           "cuda-ploc",           "cuda-sah",     "cuda-sbvh",
                        "cuda-kdtree", "cuda-lbvh-persistent", "cuda-sah-persistent", "embree-medium"};
  options.deform_frames = 3;
  const BenchReport report = run_accel_bench(scene, options);
  ASSERT_EQ(report.structures.size(), options.structures.size());
  for (const StructureResult& result : report.structures) {
    EXPECT_TRUE(result.mrays_per_s.has_value()) << result.name;
    if (result.name.starts_with("cuda-") && result.name != "cuda-kdtree") {
      EXPECT_TRUE(result.sah.has_value()) << result.name;
      EXPECT_TRUE(result.nodes.has_value()) << result.name;
    }
  }
  bool sbvh_seen = false;
  for (const DeformResult& deform : report.deform) {
    if (deform.name == "cuda-sbvh" || deform.name == "cuda-kdtree") {
      sbvh_seen = true;
      EXPECT_FALSE(deform.refit_ms.has_value());
    }
    if (deform.name == "cuda-lbvh") {
      EXPECT_TRUE(deform.refit_ms.has_value());
    }
  }
  EXPECT_TRUE(sbvh_seen);
  const auto kdtree = std::find_if(report.structures.begin(), report.structures.end(),
                                   [](const StructureResult& r) { return r.name == "cuda-kdtree"; });
  ASSERT_NE(kdtree, report.structures.end());
  EXPECT_TRUE(kdtree->nodes.has_value());
}

TEST(AccelBenchRun, OneBuildRunReportsThatBuildAndNoneIsAnError) {
  Scene scene = glint::testing::make_tiny_scene(4);
  BenchOptions options = small_options();
  options.structures = {"sah", "lbvh"};
  options.deform_frames = 0;
  options.build_runs = 1;
  const BenchReport report = run_accel_bench(scene, options);
  EXPECT_EQ(report.build_runs, 1);
  for (const StructureResult& r : report.structures) EXPECT_EQ(r.build_ms, r.first_build_ms) << r.name;
  options.build_runs = 0;
  EXPECT_NE(glint::testing::error_of([&] { (void)run_accel_bench(scene, options); }).find("build runs must be at least 1"),
            std::string::npos);
}

TEST(AccelBenchRun, JsonHasTheMachineAndOneRowPerStructure) {
  Scene scene = glint::testing::make_tiny_scene(4);
  BenchOptions options = small_options();
  options.deform_frames = 2;
  const BenchReport report = run_accel_bench(scene, options);
  const glint::testing::TempFolder folder;
  const auto path = folder.path() / "bench.json";
  write_json_atomically(path, report_json(report, current_machine(3)));
  const nlohmann::json j = nlohmann::json::parse(glint::testing::read_text_file(path));
  EXPECT_EQ(j["machine"]["threads"], 3);
  EXPECT_FALSE(j["machine"]["cpu"].get<std::string>().empty());
  EXPECT_EQ(j["scene"]["name"], "tiny");
  EXPECT_EQ(j["rays"]["count"], report.ray_count);
  ASSERT_EQ(j["structures"].size(), options.structures.size());
  for (size_t i = 0; i < options.structures.size(); ++i) EXPECT_EQ(j["structures"][i]["name"], options.structures[i]);
  EXPECT_EQ(j["deformation"]["structures"].size(), options.structures.size());
  EXPECT_EQ(j["build_runs"], options.build_runs);
  for (size_t i = 0; i < options.structures.size(); ++i) {
    EXPECT_EQ(j["structures"][i]["build_ms"].get<double>(), report.structures[i].build_ms);
    EXPECT_EQ(j["structures"][i]["first_build_ms"].get<double>(), report.structures[i].first_build_ms);
  }
  for (size_t i = 0; i < options.structures.size(); ++i) {
    EXPECT_EQ(j["structures"][i]["disagreements"], 0) << options.structures[i];
    EXPECT_TRUE(j["structures"][i]["disagreement"].is_null()) << options.structures[i];
  }
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder.path()), {}), 1);  // no temp file left
  EXPECT_THROW(write_json_atomically(folder.path() / "missing" / "x.json", j), Error);
}

// The --json path is checked before the run: a folder, a missing folder or a file in place of the
// folder fail at once, naming the path; a good path leaves nothing behind.
TEST(AccelBenchRun, JsonPathIsCheckedWithoutLeavingAFile) {
  const glint::testing::TempFolder folder;
  check_json_path(folder.path() / "out.json");
  check_json_path(folder.path() / "out.json");  // twice: the probe's temporary is gone
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder.path()), {}), 0);
  const auto missing = folder.path() / "missing" / "out.json";
  EXPECT_NE(glint::testing::error_of([&] { check_json_path(missing); }).find("cannot write '" + missing.string() + "': folder"),
            std::string::npos);
  EXPECT_NE(glint::testing::error_of([&] { check_json_path(folder.path()); }).find("it is a folder"), std::string::npos);
  const auto file = folder.write("file", "x");
  EXPECT_NE(glint::testing::error_of([&] { check_json_path(file / "out.json"); }).find("is not a folder"),
            std::string::npos);
  if (::geteuid() != 0) {  // root writes everywhere
    const auto read_only = folder.path() / "read-only";
    std::filesystem::create_directory(read_only);
    std::filesystem::permissions(read_only, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
    EXPECT_NE(glint::testing::error_of([&] { check_json_path(read_only / "out.json"); }).find("Permission denied"),
              std::string::npos);
    std::filesystem::permissions(read_only, std::filesystem::perms::owner_all);
  }
}

}  // namespace
}  // namespace glint::accel_bench

namespace glint::testing {
namespace {

TEST(AccelBenchCli, WritesValidJsonWithOneRowPerStructure) {
  const TempFolder folder;
  const auto json_path = folder.path() / "out.json";
  const CliResult r = run_glint("accel-bench atrium-simple --builders sah --rays primary --frames 1800 --width 24 "
                                "--height 16 --threads 2 --deform-frames 1 --json \"" + json_path.string() + "\"");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(read_text_file(json_path));
  ASSERT_EQ(j["structures"].size(), 5u);  // sah + Embree's four
  EXPECT_EQ(j["structures"][0]["name"], "sah");
  EXPECT_EQ(j["rays"]["count"], 24 * 16);
  EXPECT_EQ(j["machine"]["threads"], 2);
  EXPECT_EQ(j["deformation"]["frames"], 1);
  EXPECT_NE(r.out.find("embree-medium"), std::string::npos);
  EXPECT_NE(r.err.find("accel-bench: sah: built"), std::string::npos);  // progress on stderr
}

// The --json path is checked before the scene is even loaded: the error comes at once, with no
// progress line (no structure was built), and no file is left behind.
TEST(AccelBenchCli, UnwritableJsonFailsBeforeTheRun) {
  const TempFolder folder;
  const auto missing = folder.path() / "no-such-folder" / "out.json";
  for (const std::filesystem::path& json : {missing, folder.path()}) {
    const CliResult r = run_glint("accel-bench atrium-simple --builders sah --rays primary --frames 1800 --width 8 "
                                  "--height 8 --deform-frames 1 --json " + quoted(json));
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("glint: error: cannot write '" + json.string() + "'"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("accel-bench:"), std::string::npos) << "work was done before the check:\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder.path()), {}), 0);
}

// --strict-hits on a run whose structures agree: exit 0, the table with its disagree column.
TEST(AccelBenchCli, StrictHitsPassesWhenEveryStructureAgrees) {
  const CliResult r = run_glint("accel-bench atrium-simple --builders sah,trbvh-wide8 --rays primary --frames 1800 "
                                "--width 24 --height 16 --deform-frames 1 --strict-hits");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("disagree"), std::string::npos) << r.out;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
}

TEST(AccelBenchCli, BadFlagsAreUsageErrorsWithExitCode2) {
  for (const char* args : {"accel-bench --builders sah,nope", "accel-bench --frames 1800,abc", "accel-bench --frames ''",
                           "accel-bench --rays sideways", "accel-bench --width 0", "accel-bench --threads -1"}) {
    const CliResult r = run_glint(args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_TRUE(r.out.empty()) << args;
    EXPECT_LE(line_count(r.err), 2) << args << ": " << r.err;  // the reason, and CLI11's pointer to --help
  }
  const CliResult builder = run_glint("accel-bench --builders sah,nope");
  EXPECT_NE(builder.err.find("unknown builder \"nope\""), std::string::npos) << builder.err;
}

TEST(AccelBenchCli, FrameOutsideTheWalkthroughIsOneLineAndExit1) {
  const CliResult r = run_glint("accel-bench atrium-simple --frames 99999 --width 4 --height 4");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("frame 99999 is outside"), std::string::npos) << r.err;
}

TEST(AccelBenchCli, HelpExplainsEveryOption) {
  const CliResult r = run_glint("accel-bench --help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* option : {"--builders", "--rays", "--frames", "--width", "--height", "--threads", "--json",
                             "--deform-frames", "--seed", "--strict-hits", "reflection", "embree-refit"})
    EXPECT_NE(r.out.find(option), std::string::npos) << option;
}

}  // namespace
}  // namespace glint::testing
