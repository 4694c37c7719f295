#pragma once
// Shared by the wide BVH tests: building a wide BVH of either width from a binary builder, forcing
// a SIMD path for the duration of a test, and tracing a wide BVH of either width.
#include "accel/builders/builder.h"
#include "accel/wide/wide_bvh.h"
#include "accel/wide/wide_bvh_collapse.h"
#include "accel/wide/wide_bvh_trace.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace glint::accel::testing {

// A width and, for 8-wide, the kernel that traces it.
struct WideConfig {
  int width = 4;
  WideSimdPath path = WideSimdPath::sse;

  // Built by appending: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string.
  std::string name() const {
    std::string text = "w";
    text += std::to_string(width);
    if (width == 8) {
      text += '_';
      text += simd_path_name(path);
    }
    return text;
  }
};

// Every builder a wide BVH can be collapsed from: all but those with split references (sbvh).
inline std::vector<BvhBuilder> collapsible_builders() {
  std::vector<BvhBuilder> builders;
  for (const BvhBuilder builder : kAllBvhBuilders)
    if (builder != BvhBuilder::sbvh) builders.push_back(builder);
  return builders;
}

inline std::vector<WideConfig> all_wide_configs() {
  return {{4, WideSimdPath::sse}, {8, WideSimdPath::sse}, {8, WideSimdPath::avx2}};
}

// Forces the config's SIMD path while alive (tests skip AVX2 configs on CPUs without it first).
class ScopedWidePath {
public:
  explicit ScopedWidePath(const WideConfig& config) { force_wide_simd_path(config.path); }
  ~ScopedWidePath() { force_wide_simd_path(std::nullopt); }
  ScopedWidePath(const ScopedWidePath&) = delete;
  ScopedWidePath& operator=(const ScopedWidePath&) = delete;
};

using AnyWideBvh = std::variant<WideBvh4, WideBvh8>;

inline AnyWideBvh collapse_any(int width, const Bvh& bvh, const TriangleMesh& mesh,
                               const WideCollapseOptions& options = {}) {
  if (width == 4) return collapse_to_wide<4>(bvh, mesh, options);
  return collapse_to_wide<8>(bvh, mesh, options);
}

inline void trace_closest_any_width(const AnyWideBvh& bvh, std::span<const Ray> rays, std::span<Hit> hits) {
  std::visit([&](const auto& wide) { trace_closest(wide, rays, hits); }, bvh);
}

inline void trace_any_any_width(const AnyWideBvh& bvh, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  std::visit([&](const auto& wide) { trace_any(wide, rays, occluded); }, bvh);
}

}  // namespace glint::accel::testing
