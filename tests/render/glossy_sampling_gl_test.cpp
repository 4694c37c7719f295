// The GLSL glossy sampler (shaders/include/glossy_sampling.glsl) computes what its C++ twin
// (render/glossy_sampling.h) computes: the same sequence points exactly, the same directions and
// weights to float rounding, and at roughness 0 exactly the GPU's own mirror direction (the GPU's
// normalize rounds differently from the CPU's, so that one is compared on the GPU).
#include "gl/embedded_shaders.h"
#include "gl/gl_check.h"
#include "gl/gl_objects.h"
#include "gl/shader_includes.h"
#include "gl/shader_program.h"
#include "render/glossy_sampling.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace glint::render {
namespace {

using GlossySamplingGl = testing::GlTest;

struct Case {  // std430: vec4, vec4, uvec4
  vec4 incident_roughness;
  vec4 normal;
  glm::uvec4 pixel_index;
};
struct Result {
  vec4 direction_weight;
  vec4 point;   // xy the sequence point
  vec4 mirror;  // normalize(reflect(incident, normal)) as the passes compute the mirror direction
};

constexpr const char* kShader = R"(#version 450 core
layout(local_size_x = 64) in;
#include "include/glossy_sampling.glsl"
struct Case { vec4 incident_roughness; vec4 normal; uvec4 pixel_index; };
struct Result { vec4 direction_weight; vec4 point; vec4 mirror; };
layout(std430, binding = 0) readonly buffer Cases { Case cases[]; };
layout(std430, binding = 1) writeonly buffer Results { Result results[]; };
void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= uint(cases.length())) return;
  const Case c = cases[i];
  const vec2 u = glossy_sample_point(c.pixel_index.xy, c.pixel_index.z);
  const vec3 l = reflection_direction(c.incident_roughness.xyz, c.normal.xyz, c.incident_roughness.w, u);
  const float w = reflection_weight(c.incident_roughness.xyz, c.normal.xyz, c.incident_roughness.w, l);
  results[i] = Result(vec4(l, w), vec4(u, 0.0, 0.0), vec4(normalize(reflect(c.incident_roughness.xyz, c.normal.xyz)), 0.0));
}
)";

TEST_F(GlossySamplingGl, GlslAndCppAgree) {
  std::vector<Case> cases;
  std::mt19937 random(99u);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  for (int i = 0; i < 512; ++i) {
    const vec3 incident = glm::normalize(vec3(uniform(random), uniform(random), uniform(random)));
    const vec3 normal = glm::normalize(vec3(uniform(random), uniform(random), uniform(random)));
    const float roughness = i % 4 == 0 ? 0.0f : 0.5f * (uniform(random) + 1.0f);
    cases.push_back({vec4(incident, roughness), vec4(normal, 0.0f),
                     glm::uvec4(static_cast<unsigned>(i * 37 % 1920), static_cast<unsigned>(i * 11 % 1080),
                                static_cast<unsigned>(i * 1000003u), 0u)});
  }
  const ExpandedShaderSource expanded = expand_shader_includes("glossy_test.comp.glsl", kShader, find_embedded_shader, "shaders/");
  ShaderProgram program =
      ShaderProgram::from_sources({{GL_COMPUTE_SHADER, "shaders/glossy_test.comp.glsl", expanded.text, expanded.files}});
  const GlBuffer input = create_buffer(std::span<const Case>(cases));
  const GlBuffer output = create_buffer(cases.size() * sizeof(Result), nullptr, GL_DYNAMIC_STORAGE_BIT);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, input.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, output.id());
  program.use();
  glDispatchCompute(static_cast<GLuint>((cases.size() + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<Result> results(cases.size());
  glGetNamedBufferSubData(output.id(), 0, static_cast<GLsizeiptr>(results.size() * sizeof(Result)), results.data());
  check_gl("glossy sampling test dispatch");

  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Case& c = cases[i];
    const vec3 incident(c.incident_roughness);
    const vec3 normal(c.normal);
    const float roughness = c.incident_roughness.w;
    const vec2 u = glossy::sample_point(glm::uvec2(c.pixel_index), c.pixel_index.z);
    EXPECT_EQ(results[i].point.x, u.x) << i;
    EXPECT_EQ(results[i].point.y, u.y) << i;
    const vec3 l = glossy::reflection_direction(incident, normal, roughness, u);
    const float w = glossy::reflection_weight(incident, normal, roughness, l);
    const vec3 gpu(results[i].direction_weight);
    if (roughness == 0.0f) {
      EXPECT_EQ(gpu, vec3(results[i].mirror)) << "case " << i << ": the mirror, bit for bit";
      EXPECT_LT(glm::distance(gpu, glm::normalize(glm::reflect(incident, normal))), 1e-5f) << "case " << i;
      EXPECT_EQ(results[i].direction_weight.w, 1.0f);
    } else {
      EXPECT_LT(glm::distance(gpu, l), 2e-4f) << "case " << i << " roughness " << roughness;
      EXPECT_NEAR(results[i].direction_weight.w, w, 2e-4f) << "case " << i;
    }
  }
}

}  // namespace
}  // namespace glint::render
