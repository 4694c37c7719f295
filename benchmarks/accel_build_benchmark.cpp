// CPU build time on the built-in `atrium` scene (618k triangles, every instance flattened to
// world-space triangles as accel-bench does), and where it goes:
//   LbvhPhases    the lbvh build step by step (triangle boxes, Morton codes and sort, the sweep
//                 that makes the radix tree, its collapse and its node pairs, the layout that
//                 gathers them); one counter per step, ms per build; `morton_bits` says whether
//                 30-bit codes sufficed
//   Build/<name>  build_bvh(builder, mesh) whole, as `glint accel-bench` times it, repeated in one
//                 process (warm: each build reuses the large blocks the last one freed, where
//                 accel-bench's first build faults them in)
//   Embree/<q>    Embree 3 at quality low / medium / high over the same triangles (a new scene each
//                 time, construction alone, like Build); Embree/low-rebuild rebuilds one scene
//                 (update_vertices), which keeps Embree's own memory between builds
// GLINT_BENCH_THREADS limits TBB's workers (default: every hardware thread).
//
//   ./build/benchmarks/glint_benchmarks --benchmark_filter='LbvhPhases|Build/|Embree/'
//   (add --benchmark_counters_tabular=true for a table of the counters)
#include "accel/builders/binary_tree.h"
#include "accel/builders/build_lbvh.h"
#include "accel/builders/builder.h"
#include "accel/builders/bvh_collapse_leaves.h"
#include "rt/embree/embree_scene.h"
#include "accel/builders/lbvh_layout.h"
#include "accel/builders/morton.h"
#include "accel/builders/primitive_bounds.h"
#include "core/stopwatch.h"
#include "rt/scene_geometry.h"
#include "scene/presets.h"

#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <cstdlib>
#include <memory>
#include <vector>

namespace glint::accel {
namespace {

using rt::EmbreeDevice;
using rt::EmbreeQuality;
using rt::EmbreeScene;

// The scene's world triangles, indexed (one vertex block per instance), exactly as `glint
// accel-bench` flattens them: Embree's builds depend on the vertex count, so a soup of three
// vertices per triangle would slow them down (by about a third on 2 threads) and flatter glint.
struct BuildFixture {
  rt::SceneGeometry geometry;
  TriangleMesh mesh;
  std::unique_ptr<tbb::global_control> threads;

  BuildFixture() {
    if (const char* limit = std::getenv("GLINT_BENCH_THREADS"))
      threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      static_cast<size_t>(std::atoi(limit)));
    geometry = rt::flatten_scene(make_preset("atrium"));
    mesh = geometry.mesh();
  }
};

const BuildFixture& fixture() {
  static const BuildFixture instance;
  return instance;
}

void LbvhPhases(benchmark::State& state) {
  const TriangleMesh& mesh = fixture().mesh;
  const BuildOptions options;
  double boxes_ms = 0, morton_ms = 0, tree_ms = 0, layout_ms = 0;
  uint32_t bits = 0;
  for (auto _ : state) {
    Stopwatch watch;
    const detail::ScratchBounds bounds = detail::scratch_triangle_bounds(mesh);
    const BuildInput input = bounds.input();
    boxes_ms += watch.lap_ms();
    MortonOrder order = sort_by_morton(input.centroids);
    bits = order.bits;
    morton_ms += watch.lap_ms();
    const detail::LbvhSweep sweep = detail::sweep_lbvh(input, order, options);
    tree_ms += watch.lap_ms();
    Bvh bvh = detail::lay_out_lbvh(sweep, std::move(order.prims), "lbvh");
    layout_ms += watch.lap_ms();
    benchmark::DoNotOptimize(bvh.nodes.data());
  }
  const auto per_build = [&](double total) {
    return benchmark::Counter(total / static_cast<double>(state.iterations()));
  };
  state.counters["boxes_ms"] = per_build(boxes_ms);
  state.counters["morton_ms"] = per_build(morton_ms);
  state.counters["tree_ms"] = per_build(tree_ms);
  state.counters["layout_ms"] = per_build(layout_ms);
  state.counters["morton_bits"] = bits;
}
BENCHMARK(LbvhPhases)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);

// Build and Embree time the construction alone (manual time): freeing a structure is not part of
// building it, and Embree's scene release takes several milliseconds of its own.
void Build(benchmark::State& state, BvhBuilder builder) {
  const TriangleMesh& mesh = fixture().mesh;
  for (auto _ : state) {
    Stopwatch watch;
    Bvh bvh = build_bvh(builder, mesh);
    state.SetIterationTime(watch.lap_ms() * 1e-3);
    benchmark::DoNotOptimize(bvh.nodes.data());
  }
  state.counters["Mprims/s"] = benchmark::Counter(static_cast<double>(mesh.triangle_count) * 1e-6 *
                                                      static_cast<double>(state.iterations()),
                                                  benchmark::Counter::kIsRate);
}
BENCHMARK_CAPTURE(Build, lbvh, BvhBuilder::lbvh)->Unit(benchmark::kMillisecond)->UseManualTime()->MinTime(1.0);
BENCHMARK_CAPTURE(Build, sah, BvhBuilder::sah)->Unit(benchmark::kMillisecond)->UseManualTime()->MinTime(1.0);
BENCHMARK_CAPTURE(Build, median, BvhBuilder::median)->Unit(benchmark::kMillisecond)->UseManualTime()->MinTime(1.0);

void Embree(benchmark::State& state, EmbreeQuality quality) {
  const TriangleMesh& mesh = fixture().mesh;
  const EmbreeDevice device;
  for (auto _ : state) {
    Stopwatch watch;
    EmbreeScene scene(device, mesh, quality);
    state.SetIterationTime(watch.lap_ms() * 1e-3);
    benchmark::DoNotOptimize(scene.triangle_count());
  }
  state.counters["Mprims/s"] = benchmark::Counter(static_cast<double>(mesh.triangle_count) * 1e-6 *
                                                      static_cast<double>(state.iterations()),
                                                  benchmark::Counter::kIsRate);
}
BENCHMARK_CAPTURE(Embree, low, EmbreeQuality::low)->Unit(benchmark::kMillisecond)->UseManualTime()->MinTime(1.0);

// Embree low rebuilding one scene again and again (new vertex positions, the same here, then a
// commit), as a per-frame rebuild would: the counterpart of Build's repeated builds, which reuse
// the memory the last one freed (parallel_array.h).
void EmbreeRebuild(benchmark::State& state) {
  const TriangleMesh& mesh = fixture().mesh;
  const EmbreeDevice device;
  EmbreeScene scene(device, mesh, EmbreeQuality::low);
  const std::span<const vec3> positions(mesh.positions, mesh.vertex_count);
  for (auto _ : state) {
    scene.update_vertices(positions);
    state.SetIterationTime(scene.update_ms() * 1e-3);
  }
  state.counters["Mprims/s"] = benchmark::Counter(static_cast<double>(mesh.triangle_count) * 1e-6 *
                                                      static_cast<double>(state.iterations()),
                                                  benchmark::Counter::kIsRate);
}
BENCHMARK(EmbreeRebuild)->Name("Embree/low-rebuild")->Unit(benchmark::kMillisecond)->UseManualTime()->MinTime(1.0);
BENCHMARK_CAPTURE(Embree, medium, EmbreeQuality::medium)->Unit(benchmark::kMillisecond)->UseManualTime()->MinTime(1.0);
BENCHMARK_CAPTURE(Embree, high, EmbreeQuality::high)->Unit(benchmark::kMillisecond)->UseManualTime()->MinTime(1.0);

}  // namespace
}  // namespace glint::accel
