// core/enum_names.h and every named enum of glint: each name parses back to its value, an unknown
// name is one glint::Error listing every known name, and a CLI11 IsMember check built from the table
// takes exactly those names.
#include "core/enum_names.h"

#include "accel/builders/builder.h"
#include "rt/embree/embree_scene.h"
#include "accel/wide/wide_bvh_trace.h"
#include "app/accel_bench/bench_run.h"
#include "app/bench/bench_summary.h"
#include "backends/registry.h"
#include "cuda/gpu_bvh_host.h"
#include "cuda/trace_kernel.h"
#include "gl/gpu_timer.h"
#include "optix/build_preference.h"
#include "render/raster_settings.h"
#include "render/reflection_mode.h"
#include "render/resolve_settings.h"
#include "render/shadow_method.h"
#include "rt/ray_tracer.h"
#include "support/error_of.h"

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <set>
#include <string>

namespace glint {
namespace {

enum class Colour { red, green };
constexpr EnumNames<Colour, 2> kColourNames{"colour", {{Colour::red, "red"}, {Colour::green, "green"}}};

// Compile-time lookups (the tables are constexpr).
static_assert(kColourNames.name_of(Colour::green) == "green");
static_assert(kColourNames.find("red") == Colour::red);
static_assert(!kColourNames.contains("blue"));
static_assert(kColourNames.values()[1] == Colour::green);

TEST(EnumNames, NameParseAndTheErrorListingTheKnownNames) {
  EXPECT_EQ(kColourNames.parse("green"), Colour::green);
  EXPECT_EQ(kColourNames.name_of(static_cast<Colour>(7)), "?");
  EXPECT_EQ(testing::error_of([] { (void)kColourNames.parse("blue"); }),
            "unknown colour \"blue\" (known: red, green)");
  EXPECT_EQ(kColourNames.joined(" | "), "red | green");
  EXPECT_EQ(kColourNames.names(), (std::vector<std::string>{"red", "green"}));
}

TEST(EnumNames, FeedsCli11Choices) {
  CLI::App app;
  std::string colour;
  app.add_option("--colour", colour)->check(CLI::IsMember(kColourNames.names()));
  EXPECT_NO_THROW(app.parse(std::string("--colour green")));
  EXPECT_EQ(colour, "green");
  EXPECT_THROW(app.parse(std::string("--colour blue")), CLI::ValidationError);
}

// Every value of `table` round-trips, names are unique, and a wrong name lists them all.
template <typename Table>
void expect_complete(const Table& table, const char* label) {
  std::set<std::string> seen;
  for (const auto value : table.values()) {
    const std::string name(table.name_of(value));
    EXPECT_NE(name, "?") << label;
    EXPECT_TRUE(seen.insert(name).second) << label << ": " << name << " twice";
    EXPECT_EQ(table.parse(name), value) << label << ": " << name;
  }
  const std::string error = testing::error_of([&] { (void)table.parse("no-such-name"); });
  EXPECT_NE(error.find("unknown " + std::string(table.what) + " \"no-such-name\" (known: " + table.joined() + ")"),
            std::string::npos)
      << label << ": " << error;
}

TEST(EnumNames, EveryNamedEnumRoundTripsAndListsItsNames) {
  expect_complete(accel::kBvhBuilderNames, "BvhBuilder");
  expect_complete(rt::kEmbreeQualityNames, "EmbreeQuality");
  expect_complete(rt::kUpdatePolicyNames, "UpdatePolicy");
  expect_complete(cuda::kTraceKernelNames, "TraceKernel");
  expect_complete(cuda::kGpuBvhBuilderNames, "GpuBvhBuilder");
  expect_complete(optix::kBuildPreferenceNames, "optix::BuildPreference");
  expect_complete(render::kReflectionModeNames, "ReflectionMode");
  expect_complete(render::kToneMapNames, "ToneMap");
  expect_complete(render::kShadowCubeDrawNames, "ShadowCubeDraw");
  expect_complete(render::kGBufferMethodNames, "GBufferMethod");
  expect_complete(render::kPrimaryVisibilityNames, "PrimaryVisibility");
  expect_complete(render::kShadowMethodNames, "ShadowMethod");
  expect_complete(accel_bench::kRayKindNames, "RayKind");
  expect_complete(backends::kDeviceNames, "backends::Device");
  expect_complete(accel::kWideSimdPathNames, "WideSimdPath");
  expect_complete(kPassTimingNames, "PassTimingMethod");
  expect_complete(bench::kCellStateNames, "CellOutcome::State");
}

TEST(EnumNames, TheNamesTheCliAndRunJsonUse) {
  EXPECT_EQ(accel::kBvhBuilderNames.joined(), "none, median, sah, sbvh, lbvh, trbvh, ploc");
  EXPECT_EQ(rt::kUpdatePolicyNames.joined(), "rebuild, refit, auto");
  EXPECT_EQ(render::kShadowCubeDrawNames.joined(), "per-face, layered");
  EXPECT_EQ(cuda::kTraceKernelNames.joined(), "one-ray-per-thread, persistent");
  EXPECT_EQ(render::kToneMapNames.joined(), "none, reinhard, aces");
}

}  // namespace
}  // namespace glint
