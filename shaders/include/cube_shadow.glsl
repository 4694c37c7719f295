// Point-light shadow visibility from the shadow cube map (ShadowCubePass: depth = near distance / m,
// m the occluder's distance from the light along the face's axis; 0 = nothing), with
// percentage-closer filtering: the lookup of ShadowMaskPass, shared
// with any pass that needs the shadow of other points (ray-traced hits). No uniforms and no sampler
// are declared here: the includer passes its samplerCube and the settings, so a fragment and a
// compute shader can both call it with their own bindings.
//
// Against acne and peter-panning (sizes in cube-map texels at the receiver's distance, so both grow
// linearly with distance from the light):
// - the receiver is first pushed along its normal (turned towards the light) by normal_offset texels;
// - its distance is reduced by a bias of constant_bias + slope_bias * tan(angle between normal and
//   light direction) * (1 + pcf radius) texels: a surface tilted by that angle changes its distance
//   by about tan(angle) per texel, across the whole PCF footprint.

struct CubeShadowSettings {
  vec3 light_position;         // world position of the point light (the cube map's centre)
  float near_distance;         // depth d stands for m = near_distance / d
  float texel_angle;           // 2 / cube size: a texel's width per unit distance at a face's centre
  float pcf_radius_texels;     // 0 = one sample
  float constant_bias_texels;
  float slope_bias_texels;
  float normal_offset_texels;
};

// The least push off the surface, in float steps of the receiver's largest coordinate.
const float kCubeShadowPositionSteps = 4.0;

// 20 directions spread over a cube around the lookup direction (corners and edge midpoints): a
// cheap 3D PCF kernel that needs no per-face tangent frame.
const vec3 kCubeShadowPcfOffsets[20] = vec3[](
  vec3(1, 1, 1), vec3(1, -1, 1), vec3(-1, -1, 1), vec3(-1, 1, 1),
  vec3(1, 1, -1), vec3(1, -1, -1), vec3(-1, -1, -1), vec3(-1, 1, -1),
  vec3(1, 1, 0), vec3(1, -1, 0), vec3(-1, -1, 0), vec3(-1, 1, 0),
  vec3(1, 0, 1), vec3(-1, 0, 1), vec3(1, 0, -1), vec3(-1, 0, -1),
  vec3(0, 1, 1), vec3(0, -1, 1), vec3(0, -1, -1), vec3(0, 1, -1));

// 1 when the cube map's nearest occluder along `direction` (from the light) is not nearer than
// receiver_distance. The texel holds the occluder's distance along the face's axis, which is the
// largest coordinate of `direction`; along the ray that is length / largest coordinate times more.
float cube_shadow_lit(samplerCube shadow_cube, float near_distance, vec3 direction, float receiver_distance) {
  // An explicit level: the map has one, and implicit derivatives are undefined outside fragment
  // shaders (hit shading is a compute shader whose neighbouring lanes hold unrelated rays).
  float depth = textureLod(shadow_cube, direction, 0.0).r;
  if (depth <= 0.0) return 1.0;  // nothing in this direction
  vec3 a = abs(direction);
  float occluder_distance = near_distance / depth * (length(direction) / max(a.x, max(a.y, a.z)));
  return receiver_distance <= occluder_distance ? 1.0 : 0.0;
}

// Visibility 0..1 of the light from world `position` with unit `normal` (either side: it is turned
// towards the light); 1 at the light's own position.
float cube_shadow_visibility(samplerCube shadow_cube, CubeShadowSettings settings, vec3 position, vec3 normal) {
  vec3 light = settings.light_position;
  vec3 to_light = light - position;
  float distance_to_light = length(to_light);
  if (distance_to_light <= 0.0) return 1.0;
  vec3 l = to_light / distance_to_light;
  vec3 n = normal;
  if (dot(n, l) < 0.0) n = -n;  // the side facing the light (surfaces are single-sided sheets)
  float cos_angle = clamp(dot(n, l), 1e-3, 1.0);
  float tan_angle = min(sqrt(1.0 - cos_angle * cos_angle) / cos_angle, 20.0);
  float texel = settings.texel_angle * distance_to_light;  // world size of one cube texel here

  // Far from the origin a stored position is exact only to a float step of its coordinates (0.0078
  // at 1e5, more than a texel near the light): the push off the surface is at least a few such steps,
  // else the surface shadows itself (docs/render.md "precision far from the origin"). Near the origin
  // the steps are far below a texel and the push is the texels' exactly.
  vec3 magnitude = abs(position);
  float position_step = 1.1920929e-7 * max(magnitude.x, max(magnitude.y, magnitude.z));
  float push = max(settings.normal_offset_texels * texel, kCubeShadowPositionSteps * position_step);
  vec3 receiver = position + n * push;
  vec3 direction = receiver - light;
  float receiver_distance = length(direction);
  float bias = texel * (settings.constant_bias_texels +
                        settings.slope_bias_texels * tan_angle * (1.0 + settings.pcf_radius_texels));
  float compare_distance = receiver_distance - bias;

  if (settings.pcf_radius_texels <= 0.0)
    return cube_shadow_lit(shadow_cube, settings.near_distance, direction, compare_distance);
  float radius = settings.pcf_radius_texels * texel / sqrt(2.0);  // offsets have length up to sqrt(3)
  float sum = 0.0;
  for (int i = 0; i < 20; ++i)
    sum += cube_shadow_lit(shadow_cube, settings.near_distance, direction + kCubeShadowPcfOffsets[i] * radius,
                           compare_distance);
  return sum / 20.0;
}
