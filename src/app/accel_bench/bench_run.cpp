#include "app/accel_bench/bench_run.h"

#include "rt/embree/embree_scene.h"
#include "app/accel_bench/candidates.h"
#include "app/accel_bench/hit_check.h"
#include "app/accel_bench/ray_generation.h"
#include "core/error.h"
#include "rt/scene_geometry.h"
#include "scene/camera_path.h"
#include "scene/sine_deformer.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <limits>

namespace glint::accel_bench {
namespace {

void report_progress(const BenchOptions& options, const std::string& line) {
  if (options.progress) options.progress(line);
}

const CandidateEntry& find_entry(const std::vector<CandidateEntry>& menu, const std::string& name) {
  for (const CandidateEntry& entry : menu)
    if (entry.name == name) return entry;
  std::string known;
  for (const CandidateEntry& entry : menu) {
    if (!known.empty()) known += ", ";
    known += entry.name;
  }
  fail("accel-bench: unknown structure \"{}\" (known: {})", name, known);
}

// The rays of every requested frame, appended in frame order.
std::vector<accel::Ray> make_rays(const Scene& scene, const rt::SceneGeometry& geometry, const rt::EmbreeDevice& device,
                                  const BenchOptions& options) {
  if (options.rays == RayKind::random) {
    const size_t count = static_cast<size_t>(options.width) * static_cast<size_t>(options.height) *
                         std::max<size_t>(1, options.frames.size());
    return random_rays(geometry.bounds(), count, options.seed);
  }
  if (options.frames.empty()) fail("accel-bench: no frames given for {} rays", ray_kind_name(options.rays));
  const WalkthroughAnimation animation(scene);
  // Reflection rays start where primary rays hit: found with Embree, outside of any timing.
  std::optional<rt::EmbreeScene> tracer;
  if (options.rays == RayKind::reflection) tracer.emplace(device, geometry.mesh(), rt::EmbreeQuality::medium);
  std::vector<accel::Ray> rays;
  for (const int frame : options.frames) {
    if (frame < 0 || frame >= animation.frame_count())
      fail("accel-bench: frame {} is outside the walkthrough of scene '{}' (frames 0..{})", frame, scene.name,
           animation.frame_count() - 1);
    const PinholeCamera camera = make_pinhole_camera(animation.at(frame).camera, options.width, options.height);
    std::vector<accel::Ray> primary = primary_rays(camera);
    if (options.rays == RayKind::primary) {
      rays.insert(rays.end(), primary.begin(), primary.end());
      continue;
    }
    std::vector<accel::Hit> hits(primary.size());
    tracer->trace_closest(primary, hits);
    const std::vector<accel::Ray> reflected = reflection_rays(primary, hits, geometry, scene);
    rays.insert(rays.end(), reflected.begin(), reflected.end());
  }
  return rays;
}

double seconds_of(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void run_static(const BenchOptions& options, const std::vector<CandidateEntry>& menu, const accel::TriangleMesh& mesh,
                std::span<const accel::Ray> rays, BenchReport& report) {
  const HitGeometry checked = hit_geometry(mesh);
  std::vector<accel::Hit> reference_hits, hits(rays.size());
  for (const std::string& name : options.structures) {
    report_progress(options, fmt::format("accel-bench: {}: building over {} triangles", name, mesh.triangle_count));
    Candidate candidate = find_entry(menu, name).make();
    StructureResult result;
    result.name = name;
    std::vector<double> builds;
    for (int run = 0; run < options.build_runs; ++run) builds.push_back(candidate.build(mesh));  // keeps the last
    result.first_build_ms = builds.front();
    std::sort(builds.begin(), builds.end());
    result.build_ms = builds.size() % 2 == 1 ? builds[builds.size() / 2]
                                             : 0.5 * (builds[builds.size() / 2 - 1] + builds[builds.size() / 2]);
    result.mprims_per_s = result.build_ms > 0.0 ? mesh.triangle_count / (result.build_ms * 1e3) : 0.0;
    const CandidateStats stats = candidate.stats();
    result.nodes = stats.nodes;
    result.memory_bytes = stats.memory_bytes;
    result.sah = stats.sah;
    const double work = static_cast<double>(rays.size()) * mesh.triangle_count;
    if (candidate.brute_force && work > options.brute_force_limit) {
      result.skipped = fmt::format("brute force: {:.3g} ray-triangle tests", work);
      report_progress(options, fmt::format("accel-bench: {}: built in {:.1f} ms, not traced ({})", name,
                                           result.build_ms, result.skipped));
      report.structures.push_back(result);
      continue;
    }
    // Warm-up run: its hits are the ones checked.
    candidate.trace_closest(rays, hits);
    if (options.tamper_hits) options.tamper_hits(name, hits);
    if (report.reference.empty()) {
      report.reference = name;
      reference_hits = hits;
      report.ray_hits = static_cast<size_t>(std::count_if(hits.begin(), hits.end(), [](const accel::Hit& h) { return h.valid(); }));
    } else {
      const HitCheck check = check_hits(name, report.reference, rays, reference_hits, hits, checked);
      result.disagreements = check.disagreements;
      result.edge_grazes = check.edge_grazes;
      result.hit_problem = check.problem;
    }
    double best = std::numeric_limits<double>::infinity();
    for (int run = 0; run < options.timed_runs; ++run)
      best = std::min(best, candidate.trace_closest_timed ? candidate.trace_closest_timed(rays, hits)
                                                          : seconds_of([&] { candidate.trace_closest(rays, hits); }));
    result.mrays_per_s = best > 0.0 ? static_cast<double>(rays.size()) / best * 1e-6 : 0.0;
    report_progress(options, fmt::format("accel-bench: {}: built in {:.1f} ms, {:.2f} Mrays/s{}", name, result.build_ms,
                                         *result.mrays_per_s,
                                         result.disagreements != 0
                                             ? fmt::format(", {} rays disagree with {}", result.disagreements,
                                                           report.reference)
                                             : std::string()));
    report.structures.push_back(result);
  }
  const auto medium = std::find_if(report.structures.begin(), report.structures.end(),
                                   [](const StructureResult& r) { return r.name == "embree-medium"; });
  if (medium != report.structures.end() && medium->mrays_per_s && *medium->mrays_per_s > 0.0)
    for (StructureResult& result : report.structures)
      if (result.mrays_per_s) result.ratio_to_embree_medium = *result.mrays_per_s / *medium->mrays_per_s;
}

void run_deform(Scene& scene, const BenchOptions& options, const std::vector<CandidateEntry>& menu, BenchReport& report) {
  const std::vector<uint32_t> deformable = scene.deformable_meshes();
  if (options.deform_frames <= 0 || deformable.empty()) return;
  for (uint32_t mesh : deformable) report.deformable_meshes.push_back(scene.meshes[mesh].name);
  report.deform_frames = options.deform_frames;
  SceneDeformers deformers(scene);
  (void)deformers.apply(scene, 0);
  rt::SceneGeometry geometry = rt::flatten_scene(scene, deformable);
  const accel::TriangleMesh mesh = geometry.mesh();
  report.deformable_triangles = mesh.triangle_count;

  // Two of each: one refitted every frame, one rebuilt every frame.
  struct Pair {
    Candidate refitted, rebuilt;
    DeformResult result;
    double refit_sum = 0.0, rebuild_sum = 0.0;
    bool can_refit = true;
  };
  std::vector<Pair> pairs;
  for (const std::string& name : options.structures) {
    const CandidateEntry& entry = find_entry(menu, name);
    Pair pair{entry.make(), entry.make(), {}, 0.0, 0.0, true};
    pair.result.name = name;
    pair.refitted.build(mesh);
    pair.rebuilt.build(mesh);
    pairs.push_back(std::move(pair));
  }
  report_progress(options, fmt::format("accel-bench: deforming {} triangles for {} frames", mesh.triangle_count,
                                       options.deform_frames));
  for (int frame = 1; frame <= options.deform_frames; ++frame) {
    const std::vector<uint32_t> dirty = deformers.apply(scene, frame);
    rt::update_deformed(geometry, scene, dirty);
    for (Pair& pair : pairs) {
      pair.rebuild_sum += pair.rebuilt.build(mesh);
      if (!pair.can_refit) continue;
      const std::optional<double> ms = pair.refitted.refit(mesh);
      if (ms) pair.refit_sum += *ms;
      else pair.can_refit = false;
    }
  }
  // The refitted structures must still find what the rebuilt ones find.
  const std::vector<accel::Ray> rays = random_rays(geometry.bounds(), 20000, options.seed + 1);
  const HitGeometry checked = hit_geometry(mesh);
  std::vector<accel::Hit> refit_hits(rays.size()), rebuild_hits(rays.size());
  for (Pair& pair : pairs) {
    DeformResult& result = pair.result;
    result.rebuild_ms = pair.rebuild_sum / options.deform_frames;
    if (pair.can_refit) {
      result.refit_ms = pair.refit_sum / options.deform_frames;
      const double work = static_cast<double>(rays.size()) * mesh.triangle_count;
      if (!pair.refitted.brute_force || work <= options.brute_force_limit) {
        pair.refitted.trace_closest(rays, refit_hits);
        pair.rebuilt.trace_closest(rays, rebuild_hits);
        const HitCheck check = check_hits(result.name + " (refitted)", result.name + " (rebuilt)", rays, rebuild_hits,
                                          refit_hits, checked);
        result.disagreements = check.disagreements;
        result.hit_problem = check.problem;
      }
      const auto refit_sah = pair.refitted.stats().sah, rebuild_sah = pair.rebuilt.stats().sah;
      if (refit_sah && rebuild_sah && *rebuild_sah > 0.0) result.sah_drift = *refit_sah / *rebuild_sah;
    }
    report_progress(options, fmt::format("accel-bench: {}: rebuild {:.2f} ms, refit {} per frame", result.name,
                                         result.rebuild_ms,
                                         result.refit_ms ? fmt::format("{:.2f} ms", *result.refit_ms) : "n/a"));
    report.deform.push_back(result);
  }
}

}  // namespace

BenchReport run_accel_bench(Scene& scene, const BenchOptions& options) {
  if (options.structures.empty()) fail("accel-bench: no structures to compare");
  if (options.timed_runs < 1) fail("accel-bench: timed runs must be at least 1, not {}", options.timed_runs);
  if (options.build_runs < 1) fail("accel-bench: build runs must be at least 1, not {}", options.build_runs);
  if (options.width < 1 || options.height < 1)
    fail("accel-bench: image size {}x{} must be at least 1x1", options.width, options.height);
  if (options.deform_frames < 0) fail("accel-bench: deform frames must be >= 0, not {}", options.deform_frames);
  const rt::EmbreeDevice device;
  const std::vector<CandidateEntry> menu = candidate_menu(device);
  for (const std::string& name : options.structures) (void)find_entry(menu, name);  // fail before any work

  BenchReport report;
  report.scene = scene.name;
  report.scene_triangles = scene.triangle_count();
  report.scene_vertices = scene.vertex_count();
  report.instances = scene.instances.size();
  report.ray_kind = options.rays;
  report.frames = options.frames;
  report.width = options.width;
  report.build_runs = options.build_runs;
  report.height = options.height;

  {
    const rt::SceneGeometry geometry = rt::flatten_scene(scene);
    const std::vector<accel::Ray> rays = make_rays(scene, geometry, device, options);
    if (rays.empty())
      fail("accel-bench: no {} rays: no reflective surface is visible from frames {}", ray_kind_name(options.rays),
           fmt::join(options.frames, ","));
    report.ray_count = rays.size();
    report_progress(options, fmt::format("accel-bench: {} {} rays over {} triangles", rays.size(),
                                         ray_kind_name(options.rays), geometry.triangle_count()));
    run_static(options, menu, geometry.mesh(), rays, report);
  }
  run_deform(scene, options, menu, report);
  return report;
}

std::vector<std::string> hit_problems(const BenchReport& report) {
  std::vector<std::string> problems;
  for (const StructureResult& result : report.structures)
    if (!result.hit_problem.empty()) problems.push_back(result.hit_problem);
  for (const DeformResult& result : report.deform)
    if (!result.hit_problem.empty()) problems.push_back(result.hit_problem);
  return problems;
}

}  // namespace glint::accel_bench
