// Direct + ambient + emissive radiance of one surface point, lit by the frame's point light
// (FrameConstants): the lighting of LightingPass, shared with any pass that shades other points
// (ray-traced hits) so both give the same colour to the same surface. docs/render.md explains it.
//
//   E   = light_color * intensity / (1 + (d / range)^2) * max(dot(N, L), 0) * shadow
//   out = E * (albedo / pi + specular * (exponent + 8) / (8 pi) * max(dot(N, H), 0)^exponent)
//         + ambient_fraction * sky_color * albedo + emissive
// N is the normal turned towards the viewer (sheets are lit on the side one sees), H the half
// vector of L and the view direction. Only the direct term depends on the viewer: its specular lobe
// (H) and, where two viewers see different sides, N; SSR swaps the camera's for the reflected ray's
// with direct_radiance() (include/ssr_hit_view.glsl).
#include "include/frame_constants.glsl"
#include "include/scene_types.glsl"

const float kPi = 3.14159265358979;

// The light at a surface point for one viewer: the normal turned towards it, the unit vector to the
// light, max(dot(N, L), 0) and the irradiance E above.
struct LightAtSurface {
  vec3 normal;
  vec3 to_light;
  float n_dot_l;
  vec3 irradiance;
};

LightAtSurface light_at_surface(vec3 position, vec3 normal, vec3 to_viewer, float shadow) {
  LightAtSurface s;
  s.normal = normal;
  if (dot(s.normal, to_viewer) < 0.0) s.normal = -s.normal;
  vec3 to_light = light_position_range.xyz - position;
  float d = length(to_light);
  s.to_light = to_light / max(d, 1e-6);
  s.n_dot_l = max(dot(s.normal, s.to_light), 0.0);
  float attenuation = light_color_intensity.w / (1.0 + (d / light_position_range.w) * (d / light_position_range.w));
  s.irradiance = light_color_intensity.rgb * attenuation * s.n_dot_l * shadow;
  return s;
}

// The direct term E * (albedo / pi + specular colour * normalised Blinn-Phong lobe) for the viewer
// in `to_viewer` (the one `s` was made for). albedo 0: the specular part alone.
vec3 direct_radiance(LightAtSurface s, vec3 to_viewer, vec3 albedo, GpuMaterial material) {
  vec3 h = normalize(s.to_light + to_viewer);
  float exponent = material.specular_exponent.w;
  float specular = s.n_dot_l > 0.0 ? (exponent + 8.0) / (8.0 * kPi) * pow(max(dot(s.normal, h), 0.0), exponent) : 0.0;
  return s.irradiance * (albedo / kPi + material.specular_exponent.rgb * specular);
}

// position: world position; normal: unit normal as authored (either side); to_viewer: unit vector
// from the point towards the viewer (camera or reflecting surface); albedo: linear diffuse colour
// (material colour times texture); shadow: light visibility 0..1. Returns linear HDR radiance.
vec3 surface_radiance(vec3 position, vec3 normal, vec3 to_viewer, vec3 albedo, GpuMaterial material,
                      float shadow, float ambient_fraction) {
  vec3 direct = direct_radiance(light_at_surface(position, normal, to_viewer, shadow), to_viewer, albedo, material);
  return direct + ambient_fraction * sky_color.rgb * albedo + material.emissive.rgb;
}
