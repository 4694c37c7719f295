#pragma once
// The shader-storage binding points (and the one texture unit) of the gl backend's kernels
// (shaders/include/gl_rt_*.glsl): above every binding the renderer's passes use (0..18), so a trace
// leaves their bindings alone. Keep in step with the shaders.
#include <epoxy/gl.h>

namespace glint::gl_rt {

inline constexpr GLuint kTlasRefBinding = 21;       // the TLAS leaves' instance indices
inline constexpr GLuint kVertexBinding = 22;        // object-space positions, vec4 each
inline constexpr GLuint kLeafTriangleBinding = 23;  // uvec4 per BLAS leaf slot: corners and triangle
inline constexpr GLuint kInstanceBinding = 24;      // GlInstanceRecord per instance
inline constexpr GLuint kRayBinding = 25;           // the rays of a trace (accel::Ray)
inline constexpr GLuint kResultBinding = 26;        // its results: accel::Hit, or one uint per ray
inline constexpr GLuint kRayCountBinding = 27;      // its count: the buffer's first uint
inline constexpr GLuint kFlagBinding = 28;          // the stack-overflow flag
inline constexpr GLuint kHighestBinding = kFlagBinding;

// The GPU refit's own buffers (gl_refit.h, shaders/gl_rt_refit_*.comp.glsl) take the trace's per-call
// bindings: a refit is no trace, and the structures' bindings 21..24 stay as bind() sets them.
inline constexpr GLuint kRefitNodeBinding = kRayBinding;            // the node array, written
inline constexpr GLuint kRefitLinkBinding = kResultBinding;         // per node: parent, arrival counter
inline constexpr GLuint kRefitJobBinding = kRayCountBinding;        // the BLASes of a refit
inline constexpr GLuint kRefitTransformBinding = kFlagBinding;      // per instance: object_to_world

// The SAH cost's (gl_sah_cost.h, shaders/gl_rt_sah_cost.comp.glsl) likewise: it reads the nodes
// through their texture unit, as the traces do, and writes one cost per BLAS.
inline constexpr GLuint kSahCostBinding = kResultBinding;  // per job: its BLAS's cost, a double
inline constexpr GLuint kSahJobBinding = kRayCountBinding;  // the BLASes measured
inline constexpr GLuint kSahPartialBinding = kRayBinding;    // per BLAS and work group: partial sums

// The texture unit of every BVH's accel::BvhNode array, TLAS first, read as a buffer texture (two
// RGBA32UI texels a node) rather than a storage buffer: the walk's node loads then go through the
// texture cache, which made the closest-hit trace 0.52 -> 0.47 ms on an H100 (docs/perf.md, "Tenth
// round"). Above every unit the renderer's passes use (0..4).
inline constexpr GLuint kNodeTextureUnit = 20;

}  // namespace glint::gl_rt
