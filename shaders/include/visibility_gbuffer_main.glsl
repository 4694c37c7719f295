// Visibility G-buffer, resolve: the body shared by visibility_gbuffer.comp.glsl (textureGrad) and
// visibility_gbuffer_texel_fetch.comp.glsl (trilinear from texelFetch, for software renderers).
// The includer declares local_size (8 x 8, render::kImageTileSize), the material texture array and
//   vec3 material_texel(int layer, vec2 uv, vec2 ddx, vec2 ddy)
// the linear colour of texture layer `layer` at `uv` for a pixel whose uv changes by ddx and ddy
// to the neighbouring pixels. Two programs rather than a uniform branch: llvmpipe runs both sides
// of an if, so a textureGrad behind a false uniform still cost its ~60x.
//
// Visibility G-buffer, resolve (VisibilityGBufferPass, docs/render.md): one invocation per pixel
// turns the pixel's {instance + 1, triangle} id (visibility.frag.glsl) into every G-buffer image
// GBufferPass writes, texel for texel the same: albedo + reflectivity, world position (w = 1),
// authored normal + roughness, material index + 1; background pixels (id 0) get 0 everywhere.
//
// Barycentrics: the perspective-correct weights of the pixel centre, which is what the rasteriser
// interpolates varyings with. The triangle's corners go through the same transform as gl_Position
// (clip_from_world, camera-relative); a point sum(b_i c_i) of the clip-space triangle projects to the NDC
// point p when sum(b_i (x_i - p.x w_i)) = 0 and sum(b_i (y_i - p.y w_i)) = 0, so b is the cross
// product of those two vectors, normalised to sum 1 (no division by w: corners behind the camera
// are fine). surface_point() (include/surface_point.glsl, shared with hit shading) does the rest.
//
// Texture level of detail: the raster path's texture() takes the uv's screen derivatives from the
// 2x2 pixel quad (differences of the interpolated uv between neighbouring pixel centres, on the
// triangle's plane even outside it). The same differences are computed here from the barycentrics
// of the quad's pixel centres and handed to textureGrad, so the sampler (trilinear, anisotropic)
// filters the same footprint (visibility_gbuffer.comp.glsl), or, on software renderers, to a
// trilinear filter in the shader (visibility_gbuffer_texel_fetch.comp.glsl).
#include "include/frame_constants.glsl"
#include "include/surface_point.glsl"
#include "include/surface_motion.glsl"

layout(binding = 0, rg32ui) uniform readonly uimage2D visibility_ids;
layout(binding = 1, rgba8) uniform writeonly image2D albedo_reflectivity;
layout(binding = 2, rgba32f) uniform writeonly image2D world_position;
layout(binding = 3, rgba16f) uniform writeonly image2D world_normal_roughness;
layout(binding = 4, r32ui) uniform writeonly uimage2D material_id;
// render::SurfaceMotion (src/render/surface_motion.h): written only when write_motion is 1.
layout(binding = 5, rgba16f) uniform writeonly image2D world_motion;
uniform int write_motion;

// Previous minus current world position of the point with weights (1 - u - v, u, v) of triangle
// `prim` of instance `instance_index`: the corners' displacements (exactly 0 where a corner did not
// move) interpolated with the weights surface_point() takes; 0 without a look at the vertices for a
// mesh that does not deform.
vec3 surface_world_motion(uint instance_index, uint prim, vec2 hit_uv) {
  const GpuInstance instance = instances[instance_index];
  if (mesh_moves[instance.mesh] == 0u) return vec3(0.0);
  const GpuMeshRange range = mesh_ranges[instance.mesh];
  const uint first = range.first_index + 3u * prim;
  const uint v0 = range.base_vertex + indices[first];
  const uint v1 = range.base_vertex + indices[first + 1u];
  const uint v2 = range.base_vertex + indices[first + 2u];
  return (1.0 - hit_uv.x - hit_uv.y) * vertex_world_motion(instance.model, v0, vertices[v0].position_u.xyz) +
         hit_uv.x * vertex_world_motion(instance.model, v1, vertices[v1].position_u.xyz) +
         hit_uv.y * vertex_world_motion(instance.model, v2, vertices[v2].position_u.xyz);
}

// Weights (of corners 0, 1, 2) of the point of the triangle with clip-space corners `clip` that
// projects to `ndc`; (1/3, 1/3, 1/3) for a triangle seen edge-on (the rasteriser covers no pixel
// centre of such a triangle).
vec3 perspective_barycentrics(vec4 clip[3], vec2 ndc) {
  const vec3 x = vec3(clip[0].x - ndc.x * clip[0].w, clip[1].x - ndc.x * clip[1].w, clip[2].x - ndc.x * clip[2].w);
  const vec3 y = vec3(clip[0].y - ndc.y * clip[0].w, clip[1].y - ndc.y * clip[1].w, clip[2].y - ndc.y * clip[2].w);
  const vec3 k = cross(x, y);
  const float sum = k.x + k.y + k.z;
  return sum != 0.0 ? k / sum : vec3(1.0 / 3.0);
}

// NDC of pixel `pixel`'s centre.
vec2 pixel_ndc(ivec2 pixel) { return (vec2(pixel) + 0.5) / vec2(viewport.xy) * 2.0 - 1.0; }

vec2 interpolate_uv(SceneTriangle triangle, vec3 weights) {
  return weights.x * triangle.uv[0] + weights.y * triangle.uv[1] + weights.z * triangle.uv[2];
}

void main() {
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, viewport.xy))) return;
  const uvec2 id = imageLoad(visibility_ids, pixel).xy;
  if (id.x == 0u) {
    imageStore(albedo_reflectivity, pixel, vec4(0.0));
    imageStore(world_position, pixel, vec4(0.0));
    imageStore(world_normal_roughness, pixel, vec4(0.0));
    imageStore(material_id, pixel, uvec4(0u));
    if (write_motion != 0) imageStore(world_motion, pixel, vec4(0.0));
    return;
  }

  const SceneTriangle triangle = scene_triangle(id.x - 1u, id.y);
  vec4 clip[3];
  for (int i = 0; i < 3; ++i) clip[i] = clip_from_world(triangle.position[i]);
  const vec3 weights = perspective_barycentrics(clip, pixel_ndc(pixel));
  const SurfacePoint surface = surface_point(triangle, weights.yz);

  const GpuMaterial material = materials[surface.material];
  vec3 albedo = material.diffuse.rgb;
  if (material.texture_layer >= 0) {
    // The quad's uv differences: right minus left neighbour and top minus bottom, in the quad's
    // first row and column (llvmpipe's quad-wide derivatives; NVIDIA's differ from them only in
    // which row or column of the quad they take).
    const ivec2 quad = pixel & ~1;
    const vec2 uv00 = interpolate_uv(triangle, perspective_barycentrics(clip, pixel_ndc(quad)));
    const vec2 uv10 = interpolate_uv(triangle, perspective_barycentrics(clip, pixel_ndc(quad + ivec2(1, 0))));
    const vec2 uv01 = interpolate_uv(triangle, perspective_barycentrics(clip, pixel_ndc(quad + ivec2(0, 1))));
    albedo *= material_texel(material.texture_layer, surface.uv, uv10 - uv00, uv01 - uv00);
  }
  imageStore(albedo_reflectivity, pixel, vec4(albedo, material.reflectivity));
  imageStore(world_position, pixel, vec4(surface.position, 1.0));
  imageStore(world_normal_roughness, pixel, vec4(surface.normal, material.roughness));
  imageStore(material_id, pixel, uvec4(surface.material + 1u));
  if (write_motion != 0) imageStore(world_motion, pixel, vec4(surface_world_motion(id.x - 1u, id.y, weights.yz), 0.0));
}
