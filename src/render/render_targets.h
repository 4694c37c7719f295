#pragma once
// The contract between the raster passes, SSR, the ray-traced complement (later) and resolve: the
// format and meaning of every full-screen image, and the image/texture/buffer binding points the
// shaders use. All images are width x height, row 0 at the bottom (GL convention).
#include <epoxy/gl.h>

namespace glint::render {

// G-buffer (GBufferPass writes; lighting, SSR and hit shading read).
// rgb = linear diffuse albedo (texture x material), a = reflectivity 0..1.
inline constexpr GLenum kAlbedoReflectivityFormat = GL_RGBA8;
// xyz = world-space position, w = 1 where geometry was drawn, 0 for background (sky).
inline constexpr GLenum kWorldPositionFormat = GL_RGBA32F;
// xyz = unit world-space shading normal as authored (interpolated vertex normal, never flipped
// towards the viewer, so SSR can tell a back-face hit), w = roughness.
inline constexpr GLenum kWorldNormalRoughnessFormat = GL_RGBA16F;
// material index + 1; 0 = background.
inline constexpr GLenum kMaterialIdFormat = GL_R32UI;
// Standard perspective depth of the camera's projection.
inline constexpr GLenum kDepthFormat = GL_DEPTH_COMPONENT32F;
// Visibility ids (VisibilityIdPass, only with the visibility G-buffer): x = instance + 1 (0 =
// background), y = the triangle's number in its mesh; VisibilityGBufferPass rebuilds the G-buffer.
inline constexpr GLenum kVisibilityIdFormat = GL_RG32UI;

// Shadow mask (ShadowMaskPass): 1 lit, 0 shadowed, fractional at PCF edges.
inline constexpr GLenum kShadowMaskFormat = GL_R8;
// Lit image (LightingPass): linear HDR radiance, a = 1.
inline constexpr GLenum kLitFormat = GL_RGBA16F;

// Reflection image (SsrPass writes at trusted hits; the ray-traced complement writes at failed
// pixels later): rgb = linear HDR radiance seen in the mirror direction, a = world-space length of
// the reflected ray from the surface to what it hit (0 where nothing was found yet).
inline constexpr GLenum kReflectionFormat = GL_RGBA16F;
// Failure mask (SsrPass): 1 where a reflective pixel still needs a ray-traced reflection, else 0.
inline constexpr GLenum kFailureMaskFormat = GL_R8UI;
// SSR's trusted hits, from its march to its colour fetch (shaders/include/ssr_hit.glsl).
inline constexpr GLenum kSsrHitFormat = GL_RGBA32UI;
// Final image (ResolvePass): sRGB-encoded 8-bit colour, a = 1.
inline constexpr GLenum kFinalFormat = GL_RGBA8;

// Uniform/storage binding points shared by all passes.
// FrameConstants: kFrameConstantsBinding in frame_constants.h (uniform block 0).
inline constexpr GLuint kPixelCountersBinding = 0;           // atomic counters: [0] reflective pixels, [1] SSR-failed pixels
// Storage bindings of the ray-traced complement (ray_hit_buffers.h); 1..5 are the scene's (gpu_scene.h).
inline constexpr GLuint kRayBinding = 6;          // accel::Ray[]: the ray list
inline constexpr GLuint kRayPixelBinding = 7;     // uint[]: y * width + x of each ray
inline constexpr GLuint kHitBinding = 8;          // accel::Hit[]: the ray tracer's answers
inline constexpr GLuint kRayCounterBinding = 9;   // uint[2]: [0] rays in the list, [1] reflective pixels

}  // namespace glint::render
