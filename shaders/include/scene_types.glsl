// The std430 element types of the GpuScene buffers, twins of the structs in src/render/gpu_scene.h
// (sizes 32, 16, 144 and 64 bytes there; the layouts must match member for member). Types only: the
// buffers are declared by scene_geometry.glsl, scene_instances.glsl and scene_materials.glsl, so a
// shader declares only the buffers it reads.

// One vertex: xyz object-space position and unit normal; uv rides in the w components.
struct GpuVertex { vec4 position_u; vec4 normal_v; };

// Mesh m's vertex i is vertices[base_vertex + i]; its triangle p is indices[first_index + 3p + 0..2].
struct GpuMeshRange { uint first_index; uint index_count; uint base_vertex; uint vertex_count; };

// normal_matrix is the inverse transpose of model's upper 3x3 (in a mat4 for std430).
struct GpuInstance { mat4 model; mat4 normal_matrix; uint mesh; uint material; uint pad0; uint pad1; };

// diffuse.rgb and emissive.rgb linear; specular_exponent.rgb the specular colour, .w the Blinn-Phong
// exponent; texture_layer -1 = no texture, else a layer of the material texture array.
struct GpuMaterial {
  vec4 diffuse; vec4 specular_exponent; vec4 emissive;
  float reflectivity; float roughness; int texture_layer; int pad;
};
