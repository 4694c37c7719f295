#pragma once
// accel-bench's measurements, independent of the command line: given a scene and options, build
// every structure over the scene's world triangles, check their hits against the first one, time
// their closest-hit queries, and compare rebuild with refit on the deforming meshes.
#include "accel/ray.h"
#include "core/enum_names.h"
#include "scene/scene.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace glint::accel_bench {

enum class RayKind { primary, reflection, random };

inline constexpr EnumNames<RayKind, 3> kRayKindNames{
    "ray kind", {{RayKind::primary, "primary"}, {RayKind::reflection, "reflection"}, {RayKind::random, "random"}}};

inline std::string_view ray_kind_name(RayKind kind) { return kRayKindNames.name_of(kind); }
// "primary", "reflection", "random"; glint::Error otherwise.
inline RayKind parse_ray_kind(std::string_view name) { return kRayKindNames.parse(name); }

struct BenchOptions {
  // Structures by candidate_menu() name, in this order; the first one traced is the reference.
  std::vector<std::string> structures;
  RayKind rays = RayKind::reflection;
  std::vector<int> frames{1800, 2100, 2300, 4400};  // walkthrough frames whose cameras shoot the rays
  int width = 640;
  int height = 360;
  int deform_frames = 100;  // 0 skips the deformation benchmark
  uint32_t seed = 1;        // random rays
  int timed_runs = 3;       // best of these, after one warm-up run (whose hits are checked)
  // Builds of each structure: build_ms is their median, first_build_ms the first one's (cold: it
  // faults in fresh memory that later builds partly get back from the allocator).
  int build_runs = 3;
  // Brute-force structures are not traced when rays x triangles exceeds this (hours of work).
  double brute_force_limit = 2e9;
  // Test hook: called with each structure's name and hits after its warm-up trace, before the check,
  // so a test can force a mismatch.
  std::function<void(const std::string&, std::span<accel::Hit>)> tamper_hits;
  // Progress lines (one per structure); nullptr for silence.
  std::function<void(const std::string&)> progress;
};

struct StructureResult {
  std::string name;
  double build_ms = 0.0;                // median of build_runs builds
  double first_build_ms = 0.0;          // the first of them
  double mprims_per_s = 0.0;            // triangles / build_ms
  std::optional<size_t> nodes;
  size_t memory_bytes = 0;
  std::optional<double> sah;
  std::optional<double> mrays_per_s;    // best of timed_runs; nullopt when not traced
  std::optional<double> ratio_to_embree_medium;  // mrays_per_s / embree-medium's
  std::string skipped;                  // why it was not traced, when it was not
  // The check of its hits against the reference's (hit_check.h); all 0 and empty for the reference.
  size_t disagreements = 0;             // rays whose hits disagree with the reference's
  size_t edge_grazes = 0;               // rays disagreeing with the reference on an edge graze
  std::string hit_problem;              // HitCheck::problem: empty when it agrees
};

struct DeformResult {
  std::string name;
  double rebuild_ms = 0.0;              // mean per frame
  std::optional<double> refit_ms;       // mean per frame; nullopt when the structure cannot refit
  std::optional<double> sah_drift;      // SAH(refitted) / SAH(rebuilt) after the last frame
  // The refitted copy's hits checked against the rebuilt copy's after the last frame (hit_check.h);
  // nullopt when not checked (the structure cannot refit, or brute force over too many rays).
  std::optional<size_t> disagreements;
  std::string hit_problem;              // HitCheck::problem: empty when they agree
};

struct BenchReport {
  std::string scene;
  size_t scene_triangles = 0;
  size_t scene_vertices = 0;
  size_t instances = 0;
  RayKind ray_kind = RayKind::reflection;
  std::vector<int> frames;
  int width = 0, height = 0;
  size_t ray_count = 0;
  size_t ray_hits = 0;                  // of the reference structure
  std::string reference;                // the structure every other one was checked against
  int build_runs = 0;
  std::vector<StructureResult> structures;
  // Deformation: the deformable meshes' instances alone, `deform_frames` frames of sine waves.
  std::vector<std::string> deformable_meshes;
  size_t deformable_triangles = 0;
  int deform_frames = 0;
  std::vector<DeformResult> deform;
};

// Runs the benchmark. `scene` is deformed in place by the deformation part (its deformable meshes
// end posed at the last frame). glint::Error for an unknown structure, a frame outside the
// walkthrough or no rays to trace. Hits that disagree are not errors: they are counted in the
// report (hit_problems), and the run goes on.
BenchReport run_accel_bench(Scene& scene, const BenchOptions& options);

// One line per check that failed, in the report's order: a structure that disagrees with the
// reference, or a refitted structure that disagrees with its rebuilt copy (HitCheck::problem).
std::vector<std::string> hit_problems(const BenchReport& report);

}  // namespace glint::accel_bench
