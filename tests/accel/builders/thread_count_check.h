#pragma once
// The builders' promise that their output does not depend on the number of threads: build once
// with every thread and once inside a one-thread arena, and expect identical arrays.
#include "accel/builders/build_options.h"
#include "accel/bvh.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cstring>

namespace glint::accel::testing {

using Builder = Bvh (*)(const BuildInput&, const BuildOptions&);

inline void expect_same_output_on_one_thread(Builder build, const BuildInput& input, const BuildOptions& options) {
  const Bvh parallel = build(input, options);
  Bvh serial;
  tbb::task_arena(1).execute([&] { serial = build(input, options); });
  ASSERT_EQ(parallel.nodes.size(), serial.nodes.size()) << parallel.builder;
  EXPECT_EQ(0, std::memcmp(parallel.nodes.data(), serial.nodes.data(), serial.nodes.size() * sizeof(BvhNode)))
      << parallel.builder;
  EXPECT_EQ(parallel.prim_indices, serial.prim_indices) << parallel.builder;
  EXPECT_EQ(parallel.depth, serial.depth) << parallel.builder;
}

}  // namespace glint::accel::testing
