#pragma once
// Tunables of the screen-space reflection trace (SsrPass). Nothing here is a world-space length
// except the optional max_distance: depth tolerances are fractions of view depths and screen
// quantities are pixels, so a scene scaled or moved far from the origin traces the same.
// docs/ssr.md explains each one.
namespace glint::render {

struct SsrSettings {
  // Most iterations of the hierarchical trace per ray (a step to the next cell, or a level down).
  // A ray that has not hit anything after this many fails (it goes to the ray tracer), so the cap
  // bounds the cost of a pixel without producing a wrong reflection.
  int max_steps = 256;
  // How far behind the visible surface a ray still counts as meeting it, as a fraction of the
  // surface's view depth. Behind that, the ray is hidden from the camera (see empty_behind).
  float thickness = 0.01f;
  // Longest reflected ray in world units; 0 = no limit (the near and far planes and the screen
  // bound it).
  float max_distance = 0.0f;
  // A hit with confidence below this fails (FidelityFX hybrid reflections use 0.9).
  float confidence_threshold = 0.9f;
  // Width of the screen-edge confidence band as a fraction of the screen height (all four edges,
  // the same width in pixels); 0 (the default) turns the edge term off: a hit on screen is as exact
  // near the border as anywhere, and the band only sent rays to the tracer.
  float edge_fade = 0.0f;
  // Hits whose surface the ray meets at a cosine below this (grazing) lose confidence: one pixel of
  // error there is a long way along the surface.
  float min_hit_cosine = 0.1f;
  // A hit pixel with a neighbour this many pixel footprints off the hit's tangent plane sits on a
  // silhouette (what the ray meets may be the surface behind it), a crease or a step of the surface:
  // confidence 0 there, 1 at half, so hits fail from about 0.42 footprints on. With 2 (until
  // 2026-11-27, failing from 1.2) hits beside mouldings, capitals and pillar edges passed: a neighbour
  // across a right-angled crease or a sub-pixel step lies under a footprint off the plane, and those
  // hits made sponza with every material reflective miss hybrid vs rt SSIM 0.998 (docs/perf.md,
  // "Hits at silhouettes"). A ratio of the pixel's world size: no scene scale enters it.
  float silhouette_footprints = 0.7f;
  // Rays longer on screen than this fraction of the screen diagonal lose confidence (0 at it, 1 at
  // three quarters of it): the longer the march, the more hidden space it crossed.
  float max_screen_fraction = 1.0f;
  // A ray hidden behind the visible surface (by more than the thickness) fails while it is less
  // than this fraction of the surface's view depth behind it: it is probably inside what it went
  // behind, where it would meet a face the camera cannot see. Farther behind, the space is taken
  // to be empty and the ray walks on. At or below the thickness: every hidden ray walks on.
  float empty_behind = 0.25f;
};

// Throws glint::Error naming the first setting that is out of range (see each field's comment).
void validate(const SsrSettings& settings);

}  // namespace glint::render
