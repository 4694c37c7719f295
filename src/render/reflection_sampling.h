#pragma once
// How reflection rays sample a glossy surface (docs/glossy.md): the per-frame values every
// reflection pass reads from FrameConstants::reflection_sampling (frame_constants.h), through
// shaders/include/glossy_sampling.glsl.
//   glossy            on: a material's roughness widens its reflection (GGX, visible normals);
//                     off: every surface is a mirror (the paper's reflections, bit for bit)
//   samples_per_pixel reflection samples of each pixel per frame (--spp); the frame pipeline runs
//                     the reflection passes once per sample and averages them
//   roughness_cutoff  SSR marches only pixels up to this roughness; rougher ones are left to rays
//                     (hybrid) or unreflected (ssr)
#include <epoxy/gl.h>

namespace glint::render {

struct ReflectionSamplingSettings {
  bool glossy = false;            // off by default: the paper's mirror reflections
  int samples_per_pixel = 1;       // 1..4096
  float roughness_cutoff = 0.6f;   // 0..1
};

// Throws glint::Error naming the first setting out of range.
void validate(const ReflectionSamplingSettings& settings);

// Writes FrameConstants::reflection_sampling of the uniform buffer `frame_constants` for sample
// `sample_index` (0 .. samples_per_pixel - 1) of the frame.
void write_reflection_sampling(GLuint frame_constants, const ReflectionSamplingSettings& settings, int sample_index);

}  // namespace glint::render
