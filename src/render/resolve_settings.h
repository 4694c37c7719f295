#pragma once
// Tunables of the reflection resolve: distance fade, blur (ReflectionBlurPass) and composite + tone
// map (ResolvePass). docs/ssr.md gives the formulas.
#include "core/enum_names.h"

#include <string_view>

namespace glint::render {

enum class ToneMap {
  none,      // clamp to [0, 1] only (tests compare against exact sums)
  reinhard,  // c / (1 + c) per channel
  aces,      // Narkowicz's fit of the ACES filmic curve, per channel
};

inline constexpr EnumNames<ToneMap, 3> kToneMapNames{
    "tone map", {{ToneMap::none, "none"}, {ToneMap::reinhard, "reinhard"}, {ToneMap::aces, "aces"}}};

// "none", "reinhard", "aces"; and back (an unknown name is a glint::Error listing the known ones).
inline std::string_view tone_map_name(ToneMap tone_map) { return kToneMapNames.name_of(tone_map); }
inline ToneMap tone_map_from_name(std::string_view name) { return kToneMapNames.parse(name); }

// The reflection denoiser (ReflectionDenoiser, docs/glossy.md), used instead of the blur with
// ResolveSettings::denoise.
struct DenoiseSettings {
  float max_history = 32.0f;      // frames a pixel's history averages at most (1..1024)
  float clamp_sigma = 1.5f;       // history clamped to the 3x3 mean +- this many deviations (> 0)
  float depth_tolerance = 0.02f;  // reprojected history: same plane within this x camera distance (> 0)
  float max_sigma = 4.0f;         // spatial footprint in pixels at roughness >= 0.5, first frame (>= 0)
  float depth_sigma = 0.01f;      // spatial plane-distance scale, x camera distance (> 0)
  float normal_power = 32.0f;     // spatial normal weight max(n.n', 0)^power (>= 0)
  float roughness_sigma = 0.1f;   // spatial roughness weight exp(-|dr| / sigma) (> 0)
  int iterations = 3;             // a-trous iterations, steps 1, 2, 4, ... (1..5)
};

struct ResolveSettings {
  // Distance fade of the reflection by the reflected ray's world length d (reflection.a):
  // factor 1 for d <= fade_start, falling smoothly (smoothstep) to 0 at d >= fade_end.
  // fade_end <= 0 turns the fade off (factor exactly 1). The defaults are the paper's, for its
  // atrium; ResolvePass applies the two as given.
  float fade_start = 15.0f;
  float fade_end = 30.0f;
  // FramePipeline only: true (the default) replaces fade_start and fade_end of a fade that is on
  // by the scene's (render/scene_reflection_fade.h: its file's "reflection_fade", else the paper's
  // fade scaled to the scene's bounds diagonal), so the fade follows the scene's size; false keeps
  // them as given. A fade that is off stays off either way.
  bool fade_from_scene = true;
  // Separable Gaussian blur radius in pixels (0..32), sigma = radius / 2. 0 = no blur: the
  // reflection passes through (only faded), bit-identical when the fade is off.
  int blur_radius = 2;
  // Linear scale applied to lit + reflectivity x reflection before the tone map (> 0).
  float exposure = 1.0f;
  ToneMap tone_map = ToneMap::aces;
  // --denoise on: temporal accumulation + edge-aware spatial filter (docs/glossy.md) instead of the
  // paper's blur (blur_radius is then unused; the fade applies as before).
  bool denoise = false;
  DenoiseSettings denoiser;
};

// Throws glint::Error naming the first setting that is out of range.
void validate(const ResolveSettings& settings);

}  // namespace glint::render
