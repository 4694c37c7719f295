// The gl backend's structures (src/gl_rt/gl_structure_buffers.h, docs/ray-tracer.md "gl"): every
// BLAS and the TLAS in accel::BvhNode's layout in one node array, each BLAS in its own region; the
// TLAS leaves' instance indices; per BLAS leaf slot its triangle (corner indices and the triangle's
// index in its mesh); the meshes' object-space vertices; one record per instance.
// Storage bindings 21..24 and 28 (25..27 in gl_rt_kernel.glsl) and texture unit 20 are above every
// binding the renderer's passes use, so a trace leaves their bindings alone. Keep in step with
// src/gl_rt/gl_rt_bindings.h.
// `readonly restrict`: nothing writes or aliases them during a trace, which lets a driver read them
// through its read-only (non-coherent) cache path.

// accel::BvhNode (32 bytes): interior (prim_count == 0): `first` is the left child, the right one
// follows it; leaf: prim_count slots from `first` (TLAS: of tlas_refs; BLAS: of leaf_triangles).
// Indices are local to the node's own BVH: the walk adds its region's offsets. std430 reads the C++
// struct as this one.
struct BvhNode {
  vec3 bounds_min;
  uint first;
  vec3 bounds_max;
  uint prim_count;
};

// gl_rt::GlInstanceRecord (80 bytes): the instance's world-to-object transform and where its BLAS
// lives.
struct TracerInstance {
  mat4 world_to_object;
  uint node_offset;  // the BLAS's root in the node array
  uint slot_offset;  // its first leaf slot in leaf_triangles
  uint node_count;   // 0: an empty BLAS, never hit
  uint unused;
};

// Read as two RGBA32UI texels per node (load_node), so every node is two 16-byte loads whatever the
// compiler makes of a struct, through the texture cache (gl_rt_bindings.h, kNodeTextureUnit); the
// bounds' bits are floats.
layout(binding = 20) uniform usamplerBuffer bvh_node_texels;
// The TLAS's leaf slots: instance indices.
layout(std430, binding = 21) readonly restrict buffer TracerTlasRefs { uint tlas_refs[]; };
// Object-space positions (w unused) of every mesh, one after the other.
layout(std430, binding = 22) readonly restrict buffer TracerVertices { vec4 mesh_vertices[]; };
// Per BLAS leaf slot (the BVH's primitive order) its triangle: xyz the corners' indices in
// mesh_vertices (the mesh's vertex offset added), w the triangle's index in its mesh (Hit.prim). One
// load instead of the primitive index, then the triangle's indices.
layout(std430, binding = 23) readonly restrict buffer TracerLeafTriangles { uvec4 leaf_triangles[]; };
layout(std430, binding = 24) readonly restrict buffer TracerInstances { TracerInstance tracer_instances[]; };

BvhNode load_node(uint index) {
  const uvec4 low = texelFetch(bvh_node_texels, int(2u * index));
  const uvec4 high = texelFetch(bvh_node_texels, int(2u * index + 1u));
  return BvhNode(uintBitsToFloat(low.xyz), low.w, uintBitsToFloat(high.xyz), high.w);
}

// Set to 1 by a walk whose stack would overflow (gl_rt_traverse.glsl); the host reads and clears it.
layout(std430, binding = 28) buffer TracerFlags { uint tracer_stack_overflow; };

// The TLAS is the region at the start of the node array; 0 nodes: every ray misses.
uniform uint tlas_node_count;
