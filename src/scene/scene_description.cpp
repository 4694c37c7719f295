#include "scene/scene_description.h"

#include <glm/gtc/matrix_transform.hpp>

namespace glint {

void MaterialOverrides::apply(Material& material) const {
  if (diffuse) material.diffuse = *diffuse;
  if (specular) material.specular = *specular;
  if (specular_exponent) material.specular_exponent = *specular_exponent;
  if (reflectivity) material.reflectivity = *reflectivity;
  if (roughness) material.roughness = *roughness;
  if (emissive) material.emissive = *emissive;
}

mat4 MeshTransformSpec::matrix() const {
  const vec3 radians = glm::radians(rotate_degrees);
  mat4 m = glm::translate(mat4(1.0f), translate);
  // Each call multiplies on the right, so the last one written is applied to a point first.
  m = glm::rotate(m, radians.z, vec3(0.0f, 0.0f, 1.0f));
  m = glm::rotate(m, radians.y, vec3(0.0f, 1.0f, 0.0f));
  m = glm::rotate(m, radians.x, vec3(1.0f, 0.0f, 0.0f));
  return glm::scale(m, scale);
}

}  // namespace glint
