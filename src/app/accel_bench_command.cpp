#include "app/accel_bench_command.h"

#include "app/accel_bench/bench_run.h"
#include "app/accel_bench/candidates.h"
#include "app/accel_bench/candidates_optix.h"
#include "app/accel_bench/report_json.h"
#include "app/accel_bench/report_table.h"
#include "core/error.h"
#include "core/log.h"
#include "scene/load_scene.h"

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <algorithm>
#include <charconv>
#include <cstdio>

namespace glint {
namespace {

std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> parts;
  size_t start = 0;
  for (;;) {
    const size_t comma = text.find(',', start);
    parts.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) return parts;
    start = comma + 1;
  }
}

// CLI11 validators return an error text ("" for valid); reuse the parsers' messages.
template <typename Parse>
CLI::Validator validator_of(Parse parse, const char* description) {
  return CLI::Validator(
      [parse](std::string& text) -> std::string {
        try {
          (void)parse(text);
        } catch (const Error& e) {
          return e.what();
        }
        return {};
      },
      description);
}

}  // namespace

std::vector<std::string> parse_structure_list(const std::string& text, const std::string& backend) {
  const std::vector<std::string> known = accel_bench::candidate_names();
  const std::vector<std::string> cuda = accel_bench::cuda_candidate_names();
  const std::vector<std::string> optix = accel_bench::optix_candidate_names();
  const std::vector<std::string> embree = accel_bench::embree_candidate_names();
  const auto contains = [](const std::vector<std::string>& list, const std::string& name) {
    return std::find(list.begin(), list.end(), name) != list.end();
  };
  if (backend != "cpu" && backend != "cuda" && backend != "optix")
    fail("unknown accel-bench backend \"{}\" (known: cpu, cuda, optix)", backend);
  std::vector<std::string> names;
  if (text == "all") {
    for (const std::string& name : known) {
      const std::string kind = contains(cuda, name) ? "cuda" : contains(optix, name) ? "optix" : "cpu";
      if (!contains(embree, name) && kind == backend) names.push_back(name);
    }
  } else {
    for (const std::string& name : split_commas(text)) {
      if (std::find(known.begin(), known.end(), name) == known.end())
        fail("unknown builder \"{}\" (known: all, {})", name, fmt::join(known, ", "));
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
  }
  for (const std::string& name : embree)
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  return names;
}

std::vector<int> parse_frame_list(const std::string& text) {
  std::vector<int> frames;
  for (const std::string& part : split_commas(text)) {
    int frame = -1;
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), frame);
    if (part.empty() || error != std::errc() || end != part.data() + part.size() || frame < 0)
      fail("bad frame \"{}\" in \"{}\": frames are comma-separated integers >= 0", part, text);
    frames.push_back(frame);
  }
  return frames;
}

void add_accel_bench_command(CLI::App& app, AccelBenchOptions& options) {
  CLI::App* bench = app.add_subcommand(
      "accel-bench",
      "Build every acceleration structure (glint's BVH builders, Embree low/medium/high/refit) over a scene's world "
      "triangles, check they agree ray by ray, and time builds, closest-hit tracing and rebuild vs refit of the "
      "deforming meshes");
  bench->add_option("scene", options.scene, "Preset (atrium, atrium-simple, sponza) or file (.obj, .gltf, .glb, .scene.json)")
      ->capture_default_str();
  bench->add_option("--builders", options.builders,
                    "Structures to compare, in order: 'all' or a comma-separated list of " +
                        fmt::format("{}", fmt::join(accel_bench::candidate_names(), ", ")) +
                        ". The Embree ones are always added. The first one traced is the reference the others' hits "
                        "are checked against")
      ->capture_default_str()
      ->check(validator_of([](const std::string& text) { return parse_structure_list(text); }, "BUILDERS"));
  bench->add_option("--backend", options.backend,
                    "What '--builders all' runs: cpu (glint's CPU structures), cuda (every builder's BVH on the GPU, "
                    "traced by the cuda backend's kernel) or optix (OptiX GASes, fast trace and fast build); GPU "
                    "times, see docs/accel-bench.md. Named structures of any kind can be mixed in --builders")
      ->capture_default_str()
      ->check(CLI::IsMember({"cpu", "cuda", "optix"}));
  bench->add_option("--rays", options.rays,
                    "Rays to trace: 'primary' (one per pixel from the walkthrough camera at each frame), 'reflection' "
                    "(mirror reflections of the primary rays at surfaces with reflectivity > 0) or 'random' (uniform "
                    "origins in the scene box, uniform directions; width x height x frames of them)")
      ->capture_default_str()
      ->check(CLI::IsMember(accel_bench::kRayKindNames.names()));
  bench->add_option("--frames", options.frames, "Comma-separated walkthrough frames whose cameras shoot the rays")
      ->capture_default_str()
      ->check(validator_of(parse_frame_list, "FRAMES"));
  bench->add_option("--width", options.width, "Image width in pixels of the ray-generating camera")
      ->capture_default_str()
      ->check(CLI::Range(1, 16384));
  bench->add_option("--height", options.height, "Image height in pixels of the ray-generating camera")
      ->capture_default_str()
      ->check(CLI::Range(1, 16384));
  bench->add_option("--threads", options.threads,
                    "Worker threads for building and tracing (glint and Embree both use TBB); 0 = all hardware threads")
      ->capture_default_str()
      ->check(CLI::Range(0, 4096));
  bench->add_option("--json", options.json,
                    "Also write every number, the machine (CPU, threads, date) and the scene's counts to this JSON file");
  bench->add_option("--deform-frames", options.deform_frames,
                    "Frames of sine deformation over which the deformable meshes' structures are rebuilt and refitted "
                    "(mean ms per frame, SAH drift at the end); 0 skips this part")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000000));
  bench->add_option("--build-runs", options.build_runs,
                    "Builds of each structure; the table shows the median build time, the JSON the first (cold) "
                    "one too")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  bench->add_option("--seed", options.seed, "Seed of the random rays")->capture_default_str();
  bench->add_flag("--strict-hits", options.strict_hits,
                  "Fail the run when any structure's hits disagree with the reference's (beyond float precision at "
                  "the hit, docs/accel-bench.md): the table and the JSON are still written, then the exit status is " +
                      std::to_string(kHitDisagreementExitCode) +
                      ". Without it disagreements are counted (column 'disagree', JSON 'disagreements'), reported "
                      "as warnings, and the exit status is 0");
}

int hit_check_exit_code(const accel_bench::BenchReport& report, bool strict_hits) {
  const std::vector<std::string> problems = accel_bench::hit_problems(report);
  for (const std::string& problem : problems)
    log_message(strict_hits ? LogLevel::error : LogLevel::warning, fmt::format("accel-bench: {}", problem));
  if (problems.empty()) return 0;
  if (!strict_hits) {
    log_warning("accel-bench: {} hit check(s) failed; the results are written (--strict-hits makes this an error)",
                problems.size());
    return 0;
  }
  log_message(LogLevel::error, fmt::format("accel-bench: {} hit check(s) failed under --strict-hits; the results are "
                                           "written, exit status {}",
                                           problems.size(), kHitDisagreementExitCode));
  return kHitDisagreementExitCode;
}

int run_accel_bench_command(const AccelBenchOptions& options) {
  const int threads = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<size_t>(threads));

  accel_bench::BenchOptions bench;
  bench.structures = parse_structure_list(options.builders, options.backend);
  bench.rays = accel_bench::parse_ray_kind(options.rays);
  bench.frames = parse_frame_list(options.frames);
  bench.width = options.width;
  bench.height = options.height;
  bench.deform_frames = options.deform_frames;
  bench.build_runs = options.build_runs;
  bench.seed = options.seed;
  bench.progress = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };

  // A bad --json path is found now, not after minutes of building and tracing.
  if (!options.json.empty()) accel_bench::check_json_path(options.json);
  Scene scene = load_scene(options.scene);
  const accel_bench::BenchReport report = accel_bench::run_accel_bench(scene, bench);
  fmt::print("{}", accel_bench::format_report_table(report));
  std::fflush(stdout);  // the table before the verdict's lines on stderr
  if (!options.json.empty())
    accel_bench::write_json_atomically(options.json, accel_bench::report_json(report, accel_bench::current_machine(threads)));
  return hit_check_exit_code(report, options.strict_hits);
}

}  // namespace glint
