#pragma once
// Dispatch sizes of glint's compute passes. The image passes (SSR, ray list, blur, resolve) run one
// invocation per pixel in 8 x 8 work groups (local_size_x = local_size_y = kImageTileSize in their
// shaders); list passes run one invocation per item in 1D groups.
#include <epoxy/gl.h>

#include <cstdint>

namespace glint::render {

inline constexpr GLuint kImageTileSize = 8;

// Work groups of `group_size` invocations that cover `items` invocations (rounded up).
inline GLuint work_groups(std::uint64_t items, GLuint group_size) {
  return static_cast<GLuint>((items + group_size - 1) / group_size);
}

// Dispatches the bound compute program over a width x height image in kImageTileSize tiles.
inline void dispatch_over_image(int width, int height) {
  glDispatchCompute(work_groups(static_cast<std::uint64_t>(width), kImageTileSize),
                    work_groups(static_cast<std::uint64_t>(height), kImageTileSize), 1);
}

}  // namespace glint::render
