#pragma once
// Internal to the refits (binary and wide): how a recursive bottom-up refit runs in parallel. The
// levels near the root fork their children as TBB tasks; below them every subtree is refitted by one
// task. Bounds are minima and maxima, so the result is the same whatever the scheduling.
#include <tbb/task_group.h>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace glint::accel::detail {

// Forking levels for a tree of `nodes` nodes of `width` children (2, 4 or 8): about one task per
// 1024 child slots below the forks (more tasks than cores even on a few thousand nodes, so stealing
// evens out unbalanced trees), none for a small tree.
inline uint32_t refit_task_levels(size_t nodes, uint32_t width) {
  const auto fork_bits = static_cast<uint32_t>(std::bit_width(width) - 1);  // log2(width)
  const auto bits = static_cast<uint32_t>(std::bit_width(nodes * width / 1024));
  return (bits + fork_bits - 1) / fork_bits;
}

// {first(), second()}, the two run as parallel tasks when `parallel`.
template <typename First, typename Second>
auto in_parallel_if(bool parallel, First&& first, Second&& second) {
  if (!parallel) {
    auto a = first();
    return std::pair{a, second()};
  }
  decltype(first()) a;
  tbb::task_group group;
  group.run([&] { a = first(); });
  auto b = second();
  group.wait();
  return std::pair{a, b};
}

}  // namespace glint::accel::detail
