#pragma once
// Tunables of the screen-space reflection march (SsrPass). Distances are world units (metres in the
// built-in scenes), screen quantities are pixels. docs/ssr.md explains each one.
namespace glint::render {

struct SsrSettings {
  // Most DDA steps per ray. A ray that has not hit anything after this many steps fails (it goes to
  // the ray tracer), so the cap bounds the cost of a pixel without producing a wrong reflection.
  int max_steps = 256;
  // Pixels advanced per step along the major screen axis (>= 1). Larger strides cover more screen
  // per step; the binary refinement below recovers the accuracy they lose.
  float stride = 2.0f;
  // Bisection steps on the last interval once a step finds an intersection (0..16).
  int refinement_steps = 6;
  // Start each ray a per-pixel pseudo-random fraction of a stride further, so stride banding turns
  // into noise that the resolve blur removes.
  bool jitter = true;
  // How far behind the depth buffer's surface a ray still counts as hitting it (screen space only
  // sees front surfaces; everything is assumed this thick).
  float thickness = 0.5f;
  // Longest reflected ray, measured from the reflecting surface.
  float max_distance = 50.0f;
  // A hit with confidence below this fails (FidelityFX hybrid reflections use 0.9).
  float confidence_threshold = 0.9f;
  // Width of the screen-edge fade band as a fraction of the screen height (applied on all four
  // edges with the same width in pixels); 0 turns the edge fade off.
  float edge_fade = 0.05f;
  // A hit closer than this to the reflecting surface is a self-intersection and fails.
  float self_hit_distance = 0.05f;
};

// Throws glint::Error naming the first setting that is out of range (see each field's comment).
void validate(const SsrSettings& settings);

}  // namespace glint::render
