#pragma once
// Turns the renderer's intermediate images (float, linear, world units) into 8-bit pictures a
// person can read, for `glint render --debug-views` and docs. Each mapping is stated here so a
// reader of the PNGs knows what a grey level means. Input images are top row first, as read back.
#include "core/image.h"
#include "core/math.h"
#include "render/frame_constants.h"
#include "render/tile_classification.h"

#include <span>

namespace glint::render {

// Albedo rgb as stored (linear, shown without encoding so dark albedos stay distinguishable).
ImageRgba8 albedo_view(const ImageRgbaF& albedo_reflectivity);
// World normal n mapped to colour 0.5 * n + 0.5; background (zero normal) black.
ImageRgba8 normal_view(const ImageRgbaF& world_normal);
// World position mapped into the scene's bounds: (p - min) / (max - min) as rgb; background black.
ImageRgba8 position_view(const ImageRgbaF& world_position, const Aabb& world_bounds);
// Distance along the camera's view axis, grey = 1 - depth / (largest depth in this image): near is
// white, the farthest geometry of the frame black; background black too. The range adapts per frame.
ImageRgba8 depth_view(const ImageRgbaF& world_position, const FrameConstants& frame);
// The red channel as grey (shadow mask: white lit; failure mask: white where SSR failed).
ImageRgba8 grey_view(const ImageRgbaF& image);
// The reflection colour through a Reinhard curve (HDR), black where no reflection was found.
ImageRgba8 reflection_view(const ImageRgbaF& reflection);
// --reflections auto's decision per 8x8 tile (classes row-major, tile_columns per row, rows bottom
// first as GL's): none black, SSR only green, SSR + rays yellow, rays only red; each tile's border
// pixel darker so the grid shows.
ImageRgba8 tile_class_view(std::span<const TileClass> classes, int tile_columns, int width, int height);
// --reflections auto: the failure mask as the debug views split the reflection by it (1 = traced):
// SSR wrote it in its own tiles only, so rays-only tiles become 1 and tiles without reflection 0.
void mark_traced_tiles(ImageRgbaF& failure_mask, std::span<const TileClass> classes, int tile_columns);

// The linear values behind the views, for `glint render --format exr` (DebugView::linear), a = 1:
// albedo, normals, positions and reflections as stored (world units, linear radiance, background 0);
// the view depth (distance along the view axis, background 0) and masks as grey; the tile classes'
// colours / 255.
ImageRgbaF opaque(ImageRgbaF image);  // the same rgb with a = 1
ImageRgbaF view_depth(const ImageRgbaF& world_position, const FrameConstants& frame);
ImageRgbaF red_as_grey(const ImageRgbaF& image);
ImageRgbaF unit_colours(const ImageRgba8& image);  // 8-bit colours as 0..1

}  // namespace glint::render
