#pragma once
// The one conversion between a Blinn-Phong exponent and a GGX roughness, used both ways by the
// loaders: glTF gives a roughness and glint needs an exponent for the highlight; an OBJ material
// without `Pr` gives only `Ns`, and glossy reflections need a roughness (docs/glossy.md).
//
// With alpha = roughness^2, the Blinn-Phong lobe of exponent n = 2 / alpha^2 - 2 has about the
// width of a GGX lobe of that alpha (Walter et al. 2007).

namespace glint {

// n = 2 / alpha^2 - 2, clamped to 1..2048 (roughness 0.5 gives 30, near glint's default of 32).
float specular_exponent_from_roughness(float roughness);

// The inverse: roughness = (2 / (n + 2))^(1/4) for n >= 0, so n = 0 gives 1 and the roughness
// falls towards 0 as n grows (n = 30 gives 0.5, n = 2048 gives 0.177). A negative or non-finite
// exponent gives 1 (a matte surface).
float roughness_from_specular_exponent(float exponent);

}  // namespace glint
