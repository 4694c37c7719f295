#pragma once
// How the point light's shadow reaches the shadow mask (docs/render.md, "Shadow methods"):
//   cube    the cube map (ShadowCubePass) filtered by PCF (ShadowMaskPass): the paper's method, the
//           default of ShadowSettings and of glint bench
//   rt      one shadow ray per lit pixel towards the light, through the ray tracer's occlusion query
//           (RayTracedShadows); no cube map unless ray-traced reflection hits still need one
//   hybrid  the cube map at a reduced size (ShadowSettings::hybrid_cube_divisor), plus shadow rays only
//           where its filtered result is uncertain (partly lit, or near a shadow or depth edge), in
//           the spirit of AMD FidelityFX Hybrid Shadows
// glint render defaults to rt: exact hard shadows of the point light, and the fastest method on both
// machines (shadow pass 0.72 against 3.45 ms on the H100, 11 against 105 ms on llvmpipe with the cpu
// backend; docs/perf.md, "GPU-first frame").
#include "core/enum_names.h"

#include <string_view>

namespace glint::render {

enum class ShadowMethod { cube, rt, hybrid };

inline constexpr EnumNames<ShadowMethod, 3> kShadowMethodNames{
    "shadow method", {{ShadowMethod::cube, "cube"}, {ShadowMethod::rt, "rt"}, {ShadowMethod::hybrid, "hybrid"}}};

// "cube", "rt", "hybrid"; parse_shadow_method is the inverse (glint::Error naming the known ones).
inline std::string_view shadow_method_name(ShadowMethod method) { return kShadowMethodNames.name_of(method); }
inline ShadowMethod parse_shadow_method(std::string_view name) { return kShadowMethodNames.parse(name); }

struct ShadowSettings {
  ShadowMethod method = ShadowMethod::cube;
  // hybrid: the cube map's face side is RasterSettings::shadow_map_size / this (at least 1), so
  // `--shadow-map-size 1024 --shadows hybrid` draws 512^2 faces
  int hybrid_cube_divisor = 2;
  // hybrid: a pixel whose 4-neighbour is farther or nearer from the camera than this fraction of its
  // own distance is near a depth edge, where a small cube map's shadows are least trustworthy
  float hybrid_depth_edge_fraction = 0.05f;

  void validate() const;  // glint::Error naming the first bad field
};

}  // namespace glint::render
