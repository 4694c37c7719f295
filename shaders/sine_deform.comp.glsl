#version 450 core
// The sine deformer on the GPU's GL side (GlSceneDeformer, docs/hybrid.md "Deformable meshes"):
// poses one deformable mesh into the scene's vertex buffer in three stages, the formulas of
// scene/sine_deform_math.h and SineDeformer (CPU) and cuda/gpu_sine_deformer.cu (CUDA):
//   stage 0, per vertex:   posed = rest moved along displace_axis by amplitude * sin(frequency *
//                          rest[wave_axis] + phase), phase = speed * time_seconds;
//   stage 1, per triangle: its area-weighted normal, cross(b - a, c - a);
//   stage 2, per vertex:   the sum of its triangles' normals in ascending triangle order (the CPU's
//                          order), normalised (+y where it vanishes), written with the position into
//                          GpuVertex, keeping u and v.
// `precise` keeps the compiler from fusing multiplies and adds, as the host and CUDA code are built.
layout(local_size_x = 64) in;

struct GpuVertex {
  vec4 position_u;
  vec4 normal_v;
};

layout(std430, binding = 1) buffer Vertices { GpuVertex vertices[]; };  // the scene's (kVertexBufferBinding)
layout(std430, binding = 12) readonly buffer Rest { vec4 rest[]; };
layout(std430, binding = 13) readonly buffer Indices { uint indices[]; };
layout(std430, binding = 14) readonly buffer VertexOffsets { uint vertex_offsets[]; };  // vertex_count + 1
layout(std430, binding = 15) readonly buffer VertexTriangles { uint vertex_triangles[]; };
layout(std430, binding = 16) buffer Posed { vec4 posed[]; };
layout(std430, binding = 17) buffer FaceNormals { vec4 face_normals[]; };

// The mesh's constants, written once per mesh and bound per mesh (GlSceneDeformer's MeshConstants,
// kMeshConstantsBinding; uniform-buffer binding 0 is FrameConstants).
layout(std140, binding = 1) uniform MeshConstants {
  int vertex_count;
  int triangle_count;
  int base_vertex;  // the mesh's first vertex in the scene's vertex buffer
  int displace_axis;
  int wave_axis;
  float amplitude;
  float frequency;
  float speed;
};

uniform float time_seconds;  // the frame's (SceneDeformers::time_at), the same for every mesh
uniform int stage;

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (stage == 0) {
    if (i >= uint(vertex_count)) return;
    precise vec3 moved = rest[i].xyz;
    precise float phase = speed * time_seconds;  // one rounded product, as the CPU's
    precise float wave = frequency * moved[wave_axis] + phase;
    moved[displace_axis] = moved[displace_axis] + amplitude * sin(wave);
    posed[i] = vec4(moved, 0.0);
  } else if (stage == 1) {
    if (i >= uint(triangle_count)) return;
    const vec3 a = posed[indices[3u * i]].xyz;
    const vec3 b = posed[indices[3u * i + 1u]].xyz;
    const vec3 c = posed[indices[3u * i + 2u]].xyz;
    precise vec3 normal = cross(b - a, c - a);
    face_normals[i] = vec4(normal, 0.0);
  } else {
    if (i >= uint(vertex_count)) return;
    precise vec3 sum = vec3(0.0);
    for (uint k = vertex_offsets[i]; k < vertex_offsets[i + 1u]; ++k) sum += face_normals[vertex_triangles[k]].xyz;
    precise float length_of_sum = length(sum);
    const bool usable = length_of_sum > 0.0 && !isinf(length_of_sum) && !isnan(length_of_sum);
    const vec3 normal = usable ? sum / length_of_sum : vec3(0.0, 1.0, 0.0);
    const uint v = uint(base_vertex) + i;
    vertices[v].position_u.xyz = posed[i].xyz;
    vertices[v].normal_v.xyz = normal;
  }
}
