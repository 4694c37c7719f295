// Hit record -> surface point: the one place where a triangle named by {instance, triangle} and a
// point on it (barycentrics) become a world position, normal, uv and material, read from the
// GpuScene buffers. Hit shading (a ray tracer's hit {instance, prim, u, v}) and the visibility
// G-buffer (a pixel's {instance, triangle} id and the barycentrics of its centre) both call it, so a
// surface seen directly and one seen in a reflection are rebuilt the same way.
//
//   SceneTriangle triangle = scene_triangle(instance, prim);   // vertices in world space
//   SurfacePoint point = surface_point(triangle, vec2(u, v)); // weights (1 - u - v, u, v)
// The split lets a caller that needs the triangle's corners first (the visibility G-buffer finds
// the barycentrics from them) fetch the vertices once.
#include "include/scene_buffers.glsl"

struct SceneTriangle {
  vec3 position[3];       // world space: the instance's model matrix applied
  vec3 object_normal[3];  // object space, as stored
  vec2 uv[3];
  mat3 normal_matrix;     // the instance's (inverse transpose of the model's upper 3x3)
  uint material;          // index into materials[]
};

struct SurfacePoint {
  vec3 position;  // world
  vec3 normal;    // unit world normal as authored (interpolated, never flipped towards a viewer)
  vec2 uv;
  uint material;  // index into materials[]
};

// Triangle `prim` of instance `instance_index`'s mesh (mesh-local numbering, as the scene's and the
// acceleration structures').
SceneTriangle scene_triangle(uint instance_index, uint prim) {
  const GpuInstance instance = instances[instance_index];
  const GpuMeshRange range = mesh_ranges[instance.mesh];
  const uint first = range.first_index + 3u * prim;
  SceneTriangle triangle;
  for (int i = 0; i < 3; ++i) {
    const GpuVertex vertex = vertices[range.base_vertex + indices[first + uint(i)]];
    triangle.position[i] = (instance.model * vec4(vertex.position_u.xyz, 1.0)).xyz;
    triangle.object_normal[i] = vertex.normal_v.xyz;
    triangle.uv[i] = vec2(vertex.position_u.w, vertex.normal_v.w);
  }
  triangle.normal_matrix = mat3(instance.normal_matrix);
  triangle.material = instance.material;
  return triangle;
}

// The point with barycentric weights (1 - u - v, u, v) on `triangle` (accel::Hit's convention).
// The normal is interpolated in object space and transformed (linear, so the same as interpolating
// world normals); a zero interpolated normal falls back to the face normal.
SurfacePoint surface_point(SceneTriangle triangle, vec2 hit_uv) {
  const vec3 weights = vec3(1.0 - hit_uv.x - hit_uv.y, hit_uv.x, hit_uv.y);
  SurfacePoint point;
  point.position = weights.x * triangle.position[0] + weights.y * triangle.position[1] + weights.z * triangle.position[2];
  const vec3 object_normal = weights.x * triangle.object_normal[0] + weights.y * triangle.object_normal[1] +
                             weights.z * triangle.object_normal[2];
  const vec3 normal = triangle.normal_matrix * object_normal;
  point.normal = dot(normal, normal) > 0.0
                     ? normalize(normal)
                     : normalize(cross(triangle.position[1] - triangle.position[0],
                                       triangle.position[2] - triangle.position[0]));
  point.uv = weights.x * triangle.uv[0] + weights.y * triangle.uv[1] + weights.z * triangle.uv[2];
  point.material = triangle.material;
  return point;
}
