#version 450 core
// The sine deformer on the GPU's GL side (GlSceneDeformer, docs/hybrid.md "Deformable meshes"):
// poses every deformable mesh into the scene's vertex buffer in two dispatches for all meshes
// together (the meshes' arrays concatenated, a job per mesh), the formulas of
// scene/sine_deform_math.h and SineDeformer (CPU) and cuda/gpu_sine_deformer.cu (CUDA):
//   stage 0, "pose", max(vertex_count, triangle_count) invocations per mesh: invocation i below
//            vertex_count writes posed[i] = rest moved along displace_axis by amplitude *
//            sin(frequency * rest[wave_axis] + phase), phase = speed * time_seconds (and the same
//            into the gl backend's positions, where GlSceneDeformer::write_positions_to set them); below
//            triangle_count it writes triangle i's area-weighted normal, cross(b - a, c - a), posing
//            the three corners itself with the same function, so a corner is bit for bit the
//            posed[] value and the stage needs no pass of its own before it;
//   stage 1, "normals", one invocation per vertex: the sum of its triangles' normals in ascending
//            triangle order (the CPU's order), normalised (+y where it vanishes), written with the
//            position into GpuVertex, keeping u and v.
// `precise` keeps the compiler from fusing multiplies and adds, as the host and CUDA code are built.
layout(local_size_x = 64) in;

struct GpuVertex {
  vec4 position_u;
  vec4 normal_v;
};

// One deforming mesh (GlSceneDeformer's DeformJob, std430: twelve 4-byte scalars in order). The
// concatenated arrays below hold the meshes one after the other; their indices are rebased at upload
// (indices into rest[], vertex_offsets into vertex_triangles[], vertex_triangles into
// face_normals[]), so only a mesh's own first elements are needed here.
struct DeformJob {
  uint first_invocation;  // the pose stage's first invocation of the mesh (ascending, no gaps)
  uint first_vertex;      // in rest[], posed[] and vertex_offsets[]: the normals stage's first invocation
  uint first_triangle;    // in face_normals[] (3x it in indices[])
  uint vertex_count;      // > 0
  uint triangle_count;
  uint base_vertex;  // the mesh's first vertex in the scene's vertex buffer
  int displace_axis;
  int wave_axis;
  float amplitude;
  float frequency;
  float speed;
  uint target_vertex;  // the mesh's first vertex in pose_target[]; kNoTarget: not written there
};
const uint kNoTarget = 0xFFFFFFFFu;

layout(std430, binding = 1) buffer Vertices { GpuVertex vertices[]; };  // the scene's (kVertexBufferBinding)
layout(std430, binding = 12) readonly buffer Rest { vec4 rest[]; };
layout(std430, binding = 13) readonly buffer Indices { uint indices[]; };
layout(std430, binding = 14) readonly buffer VertexOffsets { uint vertex_offsets[]; };  // vertices + 1
layout(std430, binding = 15) readonly buffer VertexTriangles { uint vertex_triangles[]; };
layout(std430, binding = 16) buffer Posed { vec4 posed[]; };
layout(std430, binding = 17) buffer FaceNormals { vec4 face_normals[]; };
layout(std430, binding = 18) readonly buffer DeformJobs { DeformJob jobs[]; };  // by ascending first_invocation
layout(std430, binding = 20) writeonly buffer PoseTarget { vec4 pose_target[]; };  // the gl backend's positions

uniform float time_seconds;     // the frame's (SceneDeformers::time_at), the same for every mesh
uniform int stage;              // 0 pose, 1 normals
uniform uint job_count;         // > 0
uniform uint invocation_count;  // the stage's: the meshes' max(vertex_count, triangle_count) or vertex_count summed

// Work groups of 64 in a grid of up to 65,535 x 65,535 groups (gl_scene_deformer.cpp), so no scene
// is too large for one dispatch: main() takes its index from grid_invocation().
#include "include/grid_invocation.glsl"

// The last job whose first invocation in this stage is at or before `invocation`: thousands of
// meshes take a dozen steps.
uint job_of(uint invocation) {
  uint low = 0u, high = job_count - 1u;
  while (low < high) {
    const uint middle = (low + high + 1u) / 2u;
    const uint first = stage == 0 ? jobs[middle].first_invocation : jobs[middle].first_vertex;
    if (first <= invocation) low = middle;
    else high = middle - 1u;
  }
  return low;
}

// A rest position of the job's mesh, posed. Both the vertex's write and its triangles' normals pose
// through this, so they agree bit for bit (the operations of the earlier per-mesh stage 0, in order).
vec3 posed_position(vec3 rest_position, DeformJob job, float phase) {
  precise vec3 moved = rest_position;
  precise float wave = job.frequency * moved[job.wave_axis] + phase;
  moved[job.displace_axis] = moved[job.displace_axis] + job.amplitude * sin(wave);
  return moved;
}

void main() {
  const uint invocation = grid_invocation();
  if (invocation >= invocation_count) return;
  const DeformJob job = jobs[job_of(invocation)];
  if (stage == 0) {
    const uint i = invocation - job.first_invocation;  // the mesh's vertex i and triangle i
    precise float phase = job.speed * time_seconds;    // one rounded product, as the CPU's
    if (i < job.vertex_count) {
      const uint v = job.first_vertex + i;
      const vec4 position = vec4(posed_position(rest[v].xyz, job, phase), 0.0);
      posed[v] = position;
      if (job.target_vertex != kNoTarget) pose_target[job.target_vertex + i] = position;
    }
    if (i < job.triangle_count) {
      const uint t = job.first_triangle + i;
      const vec3 a = posed_position(rest[indices[3u * t]].xyz, job, phase);
      const vec3 b = posed_position(rest[indices[3u * t + 1u]].xyz, job, phase);
      const vec3 c = posed_position(rest[indices[3u * t + 2u]].xyz, job, phase);
      precise vec3 normal = cross(b - a, c - a);
      face_normals[t] = vec4(normal, 0.0);
    }
  } else {
    const uint v = invocation;  // in the concatenated vertices
    precise vec3 sum = vec3(0.0);
    for (uint k = vertex_offsets[v]; k < vertex_offsets[v + 1u]; ++k) sum += face_normals[vertex_triangles[k]].xyz;
    precise float length_of_sum = length(sum);
    const bool usable = length_of_sum > 0.0 && !isinf(length_of_sum) && !isnan(length_of_sum);
    const vec3 normal = usable ? sum / length_of_sum : vec3(0.0, 1.0, 0.0);
    const uint scene_vertex = job.base_vertex + (v - job.first_vertex);
    vertices[scene_vertex].position_u.xyz = posed[v].xyz;
    vertices[scene_vertex].normal_v.xyz = normal;
  }
}
