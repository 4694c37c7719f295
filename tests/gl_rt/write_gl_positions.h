#pragma once
// What a GL-side deformer does, for the gl backend's tests: the meshes' positions written into the
// tracer's vertex ranges (GlTracing::gl_positions) as vec4s with w 0, as GlSceneDeformer writes them.
#include "rt/ray_tracer.h"
#include "scene/scene.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <span>
#include <vector>

namespace glint::testing {

inline void write_gl_positions(rt::GlTracing& tracer, const Scene& scene, std::span<const std::uint32_t> meshes) {
  for (const std::uint32_t m : meshes) {
    const rt::GlTracing::VertexRange range = tracer.gl_positions(m);
    ASSERT_EQ(range.vertex_count, scene.meshes[m].positions.size());
    std::vector<vec4> widened;
    for (const vec3& p : scene.meshes[m].positions) widened.emplace_back(p, 0.0f);
    glNamedBufferSubData(range.buffer, static_cast<GLintptr>(range.offset_bytes),
                         static_cast<GLsizeiptr>(widened.size() * sizeof(vec4)), widened.data());
  }
}

}  // namespace glint::testing
