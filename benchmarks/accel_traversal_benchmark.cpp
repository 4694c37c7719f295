// CPU ray traversal throughput on the built-in `atrium` scene (618k triangles, every instance
// flattened to world-space triangles): the binary SAH BVH's single-ray kernel against the 4-wide
// (SSE) and 8-wide (AVX2, and its SSE fallback) BVHs collapsed from it, and Embree 3 at MEDIUM
// build quality when the package is found, all on the same rays in one run:
//   random      origins uniform in the scene box, uniform directions (incoherent)
//   primary     a 1280x720 camera at a walkthrough frame (coherent)
//   reflection  mirror rays from the primary hits (the rays glint's hybrid mode traces)
//   shadow      any-hit rays from the primary hits to the light (segments, t in [0, 1])
// Counters: Mrays/s, closest-hit rays per second of wall time (TBB on every core); Mrays/cpu-s,
// per second of CPU time of all the process's threads (steadier when other work shares the
// machine); hit% and differ% (hits whose validity or t differs from the binary BVH's by more than
// 1e-4 relative). GLINT_BENCH_LEAF (binary max_leaf_size) and GLINT_BENCH_MERGE (the collapse's
// merge_leaf_size) override the defaults for experiments.
//
//   ./build/benchmarks/glint_benchmarks --benchmark_counters_tabular=true
#include "accel/builders/builder.h"
#include "accel/bvh_stats.h"
#include "accel/trace.h"
#include "accel/wide/wide_bvh_collapse.h"
#include "accel/wide/wide_bvh_trace.h"
#include "core/stopwatch.h"
#include "scene/camera_path.h"
#include "scene/presets.h"

#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#if GLINT_BENCH_EMBREE
#include <embree3/rtcore.h>
#endif

#include <cmath>
#include <ctime>
#include <cstdlib>
#include <cstdio>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace glint::accel {
namespace {

constexpr int kImageWidth = 1280;
constexpr int kImageHeight = 720;
constexpr int kCameraFrame = 1800;  // one of the paper's comparison frames

struct RaySets {
  std::vector<Ray> random, primary, reflection;
  std::vector<Ray> shadow;  // from the primary hits to the light, t in [0, 1]
};

#if GLINT_BENCH_EMBREE
// Embree 3, MEDIUM quality, default scene flags, traced one ray at a time (rtcIntersect1) in the
// same TBB loop as glint's kernels.
class EmbreeScene {
public:
  explicit EmbreeScene(const std::vector<vec3>& soup) {
    device_ = rtcNewDevice(nullptr);
    scene_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_MEDIUM);
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_MEDIUM);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                                 RTC_FORMAT_FLOAT3, 3 * sizeof(float), soup.size()));
    for (size_t i = 0; i < soup.size(); ++i)
      for (int axis = 0; axis < 3; ++axis) vertices[3 * i + static_cast<size_t>(axis)] = soup[i][axis];
    auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), soup.size() / 3));
    for (size_t i = 0; i < soup.size(); ++i) indices[i] = static_cast<uint32_t>(i);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene_, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene_);
  }
  ~EmbreeScene() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  void trace_closest(std::span<const Ray> rays, std::span<Hit> hits) const {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 256), [&](const auto& range) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      for (size_t i = range.begin(); i != range.end(); ++i) {
        const Ray& ray = rays[i];
        RTCRayHit rh{};
        rh.ray.org_x = ray.origin.x, rh.ray.org_y = ray.origin.y, rh.ray.org_z = ray.origin.z;
        rh.ray.dir_x = ray.direction.x, rh.ray.dir_y = ray.direction.y, rh.ray.dir_z = ray.direction.z;
        rh.ray.tnear = ray.t_min;
        rh.ray.tfar = ray.t_max;
        rh.ray.mask = 0xFFFFFFFFu;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene_, &context, &rh);
        Hit hit;
        if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) hit = Hit{rh.ray.tfar, 0, rh.hit.primID, rh.hit.u, rh.hit.v};
        hits[i] = hit;
      }
    });
  }

  void trace_any(std::span<const Ray> rays, std::span<uint8_t> occluded) const {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 256), [&](const auto& range) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      for (size_t i = range.begin(); i != range.end(); ++i) {
        const Ray& ray = rays[i];
        RTCRay r{};
        r.org_x = ray.origin.x, r.org_y = ray.origin.y, r.org_z = ray.origin.z;
        r.dir_x = ray.direction.x, r.dir_y = ray.direction.y, r.dir_z = ray.direction.z;
        r.tnear = ray.t_min;
        r.tfar = ray.t_max;
        r.mask = 0xFFFFFFFFu;
        rtcOccluded1(scene_, &context, &r);
        occluded[i] = r.tfar < 0.0f ? 1 : 0;  // Embree sets tfar to -inf on a hit
      }
    });
  }

private:
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};
#endif

struct Fixture {
  std::vector<vec3> soup;  // world-space triangles, three corners each
  TriangleMesh mesh;
  Bvh bvh;
  WideBvh4 wide4;
  WideBvh8 wide8;
  RaySets rays;
#if GLINT_BENCH_EMBREE
  std::optional<EmbreeScene> embree;
  double embree_build_ms = 0.0;
#endif

  Fixture() {
    const Scene scene = make_preset("atrium");
    for (const Instance& instance : scene.instances) {
      const Mesh& m = scene.meshes[instance.mesh];
      for (uint32_t index : m.indices) soup.push_back(vec3(instance.transform * vec4(m.positions[index], 1.0f)));
    }
    mesh = make_triangle_soup(soup);
    BuildOptions build_options;
    if (const char* leaf = std::getenv("GLINT_BENCH_LEAF"))
      build_options.max_leaf_size = static_cast<uint32_t>(std::atoi(leaf));
    WideCollapseOptions collapse;
    if (const char* merge = std::getenv("GLINT_BENCH_MERGE"))
      collapse.merge_leaf_size = static_cast<uint32_t>(std::atoi(merge));
    bvh = build_bvh(BvhBuilder::sah, mesh, build_options);
    wide4 = collapse_to_wide<4>(bvh, mesh, collapse);
    wide8 = collapse_to_wide<8>(bvh, mesh, collapse);
    std::fprintf(stderr, "atrium: %u triangles; %s\n", mesh.triangle_count,
                 format_stats("sah", compute_stats(bvh)).c_str());
    std::fprintf(stderr,
                 "wide4: %zu nodes, %u leaves, %zu blocks, depth %u, collapse %.1f ms; "
                 "wide8: %zu nodes, %u leaves, %zu blocks, depth %u, collapse %.1f ms; 8-wide path %s\n",
                 wide4.nodes.size(), wide4.leaf_count, wide4.blocks.size(), wide4.depth, wide4.collapse_ms,
                 wide8.nodes.size(), wide8.leaf_count, wide8.blocks.size(), wide8.depth, wide8.collapse_ms,
                 std::string(simd_path_name(wide_simd_path())).c_str());
#if GLINT_BENCH_EMBREE
    const Stopwatch watch;
    embree.emplace(soup);
    embree_build_ms = watch.elapsed_ms();
    std::fprintf(stderr, "embree medium build %.1f ms\n", embree_build_ms);
#endif
    make_rays(scene);
  }

  void make_rays(const Scene& scene) {
    const Aabb box = bvh.bounds();
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::normal_distribution<float> n(0.0f, 1.0f);
    rays.random.resize(1 << 20);
    for (Ray& ray : rays.random) {
      ray.origin = box.min + vec3(u(rng), u(rng), u(rng)) * box.extent();
      ray.direction = glm::normalize(vec3(n(rng), n(rng), n(rng)) + vec3(1e-7f));
    }

    const FrameState frame = WalkthroughAnimation(scene).at(kCameraFrame);
    const CameraState camera = frame.camera;
    const vec3 forward = glm::normalize(camera.target - camera.position);
    const vec3 right = glm::normalize(glm::cross(forward, camera.up));
    const vec3 up = glm::cross(right, forward);
    const float tan_half = std::tan(glm::radians(camera.fov_y_degrees) * 0.5f);
    const float aspect = static_cast<float>(kImageWidth) / static_cast<float>(kImageHeight);
    for (int y = 0; y < kImageHeight; ++y) {
      for (int x = 0; x < kImageWidth; ++x) {
        const float sx = (2.0f * (static_cast<float>(x) + 0.5f) / kImageWidth - 1.0f) * tan_half * aspect;
        const float sy = (1.0f - 2.0f * (static_cast<float>(y) + 0.5f) / kImageHeight) * tan_half;
        Ray ray;
        ray.origin = camera.position;
        ray.direction = glm::normalize(forward + sx * right + sy * up);
        rays.primary.push_back(ray);
      }
    }

    // Mirror rays off the primary hits, started a little off the surface on the incoming side.
    std::vector<Hit> hits(rays.primary.size());
    trace_closest(bvh, mesh, rays.primary, hits);
    const float offset = 1e-4f * glm::length(box.extent());
    for (size_t i = 0; i < hits.size(); ++i) {
      if (!hits[i].valid()) continue;
      const Ray& primary = rays.primary[i];
      const Triangle tri = mesh.triangle(hits[i].prim);
      vec3 normal = glm::normalize(glm::cross(tri.v1 - tri.v0, tri.v2 - tri.v0));
      if (glm::dot(normal, primary.direction) > 0.0f) normal = -normal;
      Ray ray;
      ray.origin = primary.origin + hits[i].t * primary.direction + offset * normal;
      ray.direction = glm::reflect(primary.direction, normal);
      rays.reflection.push_back(ray);
      Ray shadow;
      shadow.origin = ray.origin;
      shadow.direction = frame.light_position - ray.origin;
      shadow.t_max = 1.0f;
      rays.shadow.push_back(shadow);
    }
    std::fprintf(stderr, "rays: %zu random, %zu primary (frame %d), %zu reflection, %zu shadow\n",
                 rays.random.size(), rays.primary.size(), kCameraFrame, rays.reflection.size(), rays.shadow.size());
  }
};

const Fixture& fixture() {
  static const Fixture instance;
  return instance;
}

enum class RaySet { random, primary, reflection };
enum class Structure { binary_sah, wide4_sse, wide8_sse, wide8_avx2, embree_medium };

const std::vector<Ray>& ray_set(RaySet set) {
  const RaySets& rays = fixture().rays;
  return set == RaySet::random ? rays.random : set == RaySet::primary ? rays.primary : rays.reflection;
}

void trace(Structure structure, std::span<const Ray> rays, std::span<Hit> hits) {
  const Fixture& f = fixture();
  switch (structure) {
    case Structure::binary_sah: trace_closest(f.bvh, f.mesh, rays, hits); break;
    case Structure::wide4_sse: trace_closest(f.wide4, rays, hits); break;
    case Structure::wide8_sse:
    case Structure::wide8_avx2: trace_closest(f.wide8, rays, hits); break;
    case Structure::embree_medium:
#if GLINT_BENCH_EMBREE
      f.embree->trace_closest(rays, hits);
#endif
      break;
  }
}

void trace_any(Structure structure, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  const Fixture& f = fixture();
  switch (structure) {
    case Structure::binary_sah: trace_any(f.bvh, f.mesh, rays, occluded); break;
    case Structure::wide4_sse: trace_any(f.wide4, rays, occluded); break;
    case Structure::wide8_sse:
    case Structure::wide8_avx2: trace_any(f.wide8, rays, occluded); break;
    case Structure::embree_medium:
#if GLINT_BENCH_EMBREE
      f.embree->trace_any(rays, occluded);
#endif
      break;
  }
}

double process_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

void closest_hit(benchmark::State& state, RaySet set, Structure structure) {
  if (structure == Structure::wide8_avx2 && !cpu_has_avx2()) {
    state.SkipWithError("no AVX2 on this CPU");
    return;
  }
  if (structure == Structure::wide8_sse) force_wide_simd_path(WideSimdPath::sse);
  if (structure == Structure::wide8_avx2) force_wide_simd_path(WideSimdPath::avx2);
  const std::vector<Ray>& rays = ray_set(set);
  std::vector<Hit> hits(rays.size());
  const double cpu_start = process_cpu_seconds();
  for (auto _ : state) {
    trace(structure, rays, hits);
    benchmark::DoNotOptimize(hits.data());
    benchmark::ClobberMemory();
  }
  const double cpu_seconds = process_cpu_seconds() - cpu_start;
  force_wide_simd_path(std::nullopt);
  // Hits agree with the binary BVH's (glint structures: the same triangle test, so the same t).
  std::vector<Hit> reference(rays.size());
  trace_closest(fixture().bvh, fixture().mesh, rays, reference);
  size_t hit_count = 0, disagree = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    hit_count += hits[i].valid() ? 1 : 0;
    const bool same = hits[i].valid() == reference[i].valid() &&
                      (!hits[i].valid() || std::abs(hits[i].t - reference[i].t) <= 1e-4f * reference[i].t);
    disagree += same ? 0 : 1;
  }
  const double mrays = static_cast<double>(rays.size()) * static_cast<double>(state.iterations()) * 1e-6;
  state.counters["Mrays/s"] = benchmark::Counter(mrays, benchmark::Counter::kIsRate);
  // Per CPU-second of all the process's threads: what a core delivers, far less disturbed than
  // wall time when other processes share the machine.
  state.counters["Mrays/cpu-s"] = mrays / cpu_seconds;
  state.counters["hit%"] = 100.0 * static_cast<double>(hit_count) / static_cast<double>(rays.size());
  state.counters["differ%"] = 100.0 * static_cast<double>(disagree) / static_cast<double>(rays.size());
}

// Shadow rays (any hit) from the primary hits to the light.
void any_hit(benchmark::State& state, Structure structure) {
  if (structure == Structure::wide8_avx2 && !cpu_has_avx2()) {
    state.SkipWithError("no AVX2 on this CPU");
    return;
  }
  if (structure == Structure::wide8_sse) force_wide_simd_path(WideSimdPath::sse);
  if (structure == Structure::wide8_avx2) force_wide_simd_path(WideSimdPath::avx2);
  const std::vector<Ray>& rays = fixture().rays.shadow;
  std::vector<uint8_t> occluded(rays.size());
  const double cpu_start = process_cpu_seconds();
  for (auto _ : state) {
    trace_any(structure, rays, occluded);
    benchmark::DoNotOptimize(occluded.data());
    benchmark::ClobberMemory();
  }
  const double cpu_seconds = process_cpu_seconds() - cpu_start;
  force_wide_simd_path(std::nullopt);
  std::vector<uint8_t> reference(rays.size());
  trace_any(fixture().bvh, fixture().mesh, rays, reference);
  size_t occluded_count = 0, disagree = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    occluded_count += occluded[i];
    disagree += occluded[i] != reference[i] ? 1 : 0;
  }
  const double mrays = static_cast<double>(rays.size()) * static_cast<double>(state.iterations()) * 1e-6;
  state.counters["Mrays/s"] = benchmark::Counter(mrays, benchmark::Counter::kIsRate);
  state.counters["Mrays/cpu-s"] = mrays / cpu_seconds;
  state.counters["hit%"] = 100.0 * static_cast<double>(occluded_count) / static_cast<double>(rays.size());
  state.counters["differ%"] = 100.0 * static_cast<double>(disagree) / static_cast<double>(rays.size());
}

void register_benchmarks() {
  const std::pair<const char*, RaySet> sets[] = {
      {"random", RaySet::random}, {"primary", RaySet::primary}, {"reflection", RaySet::reflection}};
  std::vector<std::pair<const char*, Structure>> structures = {{"binary_sah", Structure::binary_sah},
                                                               {"wide4_sse", Structure::wide4_sse},
                                                               {"wide8_sse", Structure::wide8_sse},
                                                               {"wide8_avx2", Structure::wide8_avx2}};
#if GLINT_BENCH_EMBREE
  structures.emplace_back("embree_medium", Structure::embree_medium);
#endif
  for (const auto& [set_name, set] : sets) {
    for (const auto& [structure_name, structure] : structures) {
      std::string name = "closest/";
      name += set_name;
      name += '/';
      name += structure_name;
      benchmark::RegisterBenchmark(name.c_str(), closest_hit, set, structure)
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->MinTime(1.0);
    }
  }
  for (const auto& [structure_name, structure] : structures) {
    std::string name = "any/shadow/";
    name += structure_name;
    benchmark::RegisterBenchmark(name.c_str(), any_hit, structure)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->MinTime(1.0);
  }
}

const int registered = (register_benchmarks(), 0);

}  // namespace
}  // namespace glint::accel
