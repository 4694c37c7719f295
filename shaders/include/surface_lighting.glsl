// Direct + ambient + emissive radiance of one surface point, lit by the frame's point light
// (FrameConstants): the lighting of LightingPass, shared with any pass that shades other points
// (ray-traced hits) so both give the same colour to the same surface. docs/render.md explains it.
//
//   E   = light_color * intensity / (1 + (d / range)^2) * max(dot(N, L), 0) * shadow
//   out = E * (albedo / pi + specular * (exponent + 8) / (8 pi) * max(dot(N, H), 0)^exponent)
//         + ambient_fraction * sky_color * albedo + emissive
// N is the normal turned towards the viewer (sheets are lit on the side one sees), H the half
// vector of L and the view direction.
#include "include/frame_constants.glsl"
#include "include/scene_types.glsl"

const float kPi = 3.14159265358979;

// position: world position; normal: unit normal as authored (either side); to_viewer: unit vector
// from the point towards the viewer (camera or reflecting surface); albedo: linear diffuse colour
// (material colour times texture); shadow: light visibility 0..1. Returns linear HDR radiance.
vec3 surface_radiance(vec3 position, vec3 normal, vec3 to_viewer, vec3 albedo, GpuMaterial material,
                      float shadow, float ambient_fraction) {
  vec3 n = normal;
  vec3 v = to_viewer;
  if (dot(n, v) < 0.0) n = -n;
  vec3 to_light = light_position_range.xyz - position;
  float d = length(to_light);
  vec3 l = to_light / max(d, 1e-6);
  float n_dot_l = max(dot(n, l), 0.0);
  float attenuation = light_color_intensity.w / (1.0 + (d / light_position_range.w) * (d / light_position_range.w));
  vec3 irradiance = light_color_intensity.rgb * attenuation * n_dot_l * shadow;

  vec3 h = normalize(l + v);
  float exponent = material.specular_exponent.w;
  float specular = n_dot_l > 0.0 ? (exponent + 8.0) / (8.0 * kPi) * pow(max(dot(n, h), 0.0), exponent) : 0.0;
  vec3 direct = irradiance * (albedo / kPi + material.specular_exponent.rgb * specular);
  return direct + ambient_fraction * sky_color.rgb * albedo + material.emissive.rgb;
}
