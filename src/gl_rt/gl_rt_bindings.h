#pragma once
// The shader-storage binding points of the gl backend's kernels (shaders/include/gl_rt_*.glsl): above
// every binding the renderer's passes use (0..18), so a trace leaves their bindings alone. Keep in
// step with the shaders.
#include <epoxy/gl.h>

namespace glint::gl_rt {

inline constexpr GLuint kNodeBinding = 20;          // every BVH's accel::BvhNode array, TLAS first
inline constexpr GLuint kTlasRefBinding = 21;       // the TLAS leaves' instance indices
inline constexpr GLuint kVertexBinding = 22;        // object-space positions, vec4 each
inline constexpr GLuint kLeafTriangleBinding = 23;  // uvec4 per BLAS leaf slot: corners and triangle
inline constexpr GLuint kInstanceBinding = 24;      // GlInstanceRecord per instance
inline constexpr GLuint kRayBinding = 25;           // the rays of a trace (accel::Ray)
inline constexpr GLuint kResultBinding = 26;        // its results: accel::Hit, or one uint per ray
inline constexpr GLuint kRayCountBinding = 27;      // its count: the buffer's first uint
inline constexpr GLuint kFlagBinding = 28;          // the stack-overflow flag
inline constexpr GLuint kHighestBinding = kFlagBinding;

}  // namespace glint::gl_rt
