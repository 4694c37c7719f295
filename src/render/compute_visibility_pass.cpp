#include "render/compute_visibility_pass.h"

#include "core/error.h"
#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"
#include "render/compute_dispatch.h"
#include "render/reflection_texture_check.h"
#include "render/render_targets.h"

#include <algorithm>
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

namespace glint::render {
namespace {

// Storage bindings of shaders/include/compute_visibility_buffers.glsl (1..11 are the scene's and the
// ray passes'; render_targets.h, gpu_scene.h, occlusion_buffers.h).
constexpr GLuint kDepthKeyBinding = 12;
constexpr GLuint kWinnerBinding = 13;
constexpr GLuint kLargeTriangleBinding = 14;
constexpr GLuint kTileChunkBinding = 15;
constexpr GLuint kCounterBinding = 16;
constexpr GLuint kInstanceFirstTriangleBinding = 17;
constexpr GLuint kDeferredBinding = 18;
constexpr GLuint kTouchedBinding = 19;

// The twin of the GLSL Counters block (compute_visibility_reset.comp.glsl sets the values every run
// starts from).
struct Counters {
  std::uint32_t large_count = 0;
  std::uint32_t overflowed = 0;
  std::uint32_t chunk_count = 0;
  std::uint32_t deferred_count = 0;
  std::uint32_t tile_dispatch[4] = {};      // written by the chunk-dispatch step
  std::uint32_t deferred_dispatch[4] = {};  // x counted up by the per-triangle dispatch
};
constexpr GLintptr kTileDispatchOffset = offsetof(Counters, tile_dispatch);
constexpr GLintptr kDeferredDispatchOffset = offsetof(Counters, deferred_dispatch);

constexpr std::size_t kLargeTriangleBytes = 64;  // GLSL LargeTriangle: four ivec4/vec4
constexpr std::size_t kTileChunkBytes = 8;       // GLSL uvec2: entry, first tile
constexpr GLuint kTriangleGroupSize = 64;        // compute_visibility_triangles.comp.glsl
constexpr GLuint kResetGroupSize = 256;          // compute_visibility_reset.comp.glsl
constexpr GLuint kMaxGroupsX = 65535;            // GL's guaranteed limit per dispatch dimension

// Default list size: one entry per 8 pixels, 6 times what the atrium needs (18,284 entries at
// 1280x720, frame 2100: one per 50 pixels); at least 16k entries for tiny targets. A fuller scene
// stays correct, only slower (the invocations that find the list full rasterise alone).
constexpr std::uint32_t kPixelsPerLargeTriangle = 8;
constexpr std::uint32_t kMinLargeTriangles = 16384;
// Triangle numbers leave the top bit free (kOverflowed in compute_visibility_buffers.glsl).
constexpr std::uint64_t kMaxTriangles = 0x80000000ull;

std::uint32_t capacity_for(const RasterTargets& targets, const ComputeVisibilityOptions& options) {
  if (options.large_triangle_capacity > 0) return options.large_triangle_capacity;
  const std::uint64_t pixels = static_cast<std::uint64_t>(targets.width) * static_cast<std::uint64_t>(targets.height);
  return static_cast<std::uint32_t>(std::max<std::uint64_t>(pixels / kPixelsPerLargeTriangle, kMinLargeTriangles));
}

// Default chunk list: twice the entries. An entry takes one record per 8 of its tiles (at least
// one); the atrium's 18,327 entries at 1280x720 (frame 2100) take 20,427 records. A fuller scene
// stays correct, only slower, as with the large-triangle list.
constexpr std::uint32_t kChunksPerLargeTriangle = 2;

std::uint32_t chunk_capacity_for(std::uint32_t large_capacity, const ComputeVisibilityOptions& options) {
  if (options.tile_chunk_capacity > 0) return options.tile_chunk_capacity;
  return static_cast<std::uint32_t>(
      std::min<std::uint64_t>(std::uint64_t{large_capacity} * kChunksPerLargeTriangle, 0xFFFFFFFFull));
}

// First draw-order number of each instance's triangles, and the total at the end.
std::vector<std::uint32_t> instance_first_triangles(const GpuScene& scene) {
  std::vector<std::uint32_t> first;
  first.reserve(scene.instances().size() + 1);
  std::uint64_t total = 0;
  for (const GpuInstance& instance : scene.instances()) {
    first.push_back(static_cast<std::uint32_t>(total));
    total += scene.mesh_ranges()[instance.mesh].index_count / 3;
  }
  if (total >= kMaxTriangles) fail("compute visibility: {} triangles, more than the {} it numbers", total, kMaxTriangles);
  first.push_back(static_cast<std::uint32_t>(total));
  return first;
}

std::size_t pixel_count(const RasterTargets& targets) {
  require_pass_size("compute visibility", targets.width, targets.height);
  if (targets.visibility_id.id() == 0) fail("compute visibility: the raster targets have no visibility id image");
  return static_cast<std::size_t>(targets.width) * static_cast<std::size_t>(targets.height);
}

// Work groups of the reset dispatch: one invocation per pixel, at most one dimension's worth of
// groups (compute_visibility_reset.comp.glsl strides over the pixels beyond them).
GLuint reset_groups(std::size_t pixels) { return std::min(work_groups(pixels, kResetGroupSize), kMaxGroupsX); }

void set_uint(ShaderProgram& program, const char* name, std::uint32_t value) {
  glProgramUniform1ui(program.id(), program.uniform_location(name), value);
}

bool offers_64_bit_atomics() {
  return epoxy_has_gl_extension("GL_NV_shader_atomic_int64") && epoxy_has_gl_extension("GL_ARB_gpu_shader_int64");
}

// The variant of the rasteriser's shaders (shaders/include/compute_raster_extensions.glsl).
std::span<const std::string_view> raster_defines(bool one_round) {
  static constexpr std::string_view kOneRound[] = {"GLINT_RASTER_ONE_ROUND"};
  return one_round ? std::span<const std::string_view>(kOneRound) : std::span<const std::string_view>();
}

void clear_to(const GlBuffer& buffer, std::uint32_t value) {
  glClearNamedBufferData(buffer.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &value);
}

}  // namespace

ComputeVisibilityPass::ComputeVisibilityPass(const RasterTargets& targets, const GpuScene& scene,
                                             const ComputeVisibilityOptions& options)
    : targets_(&targets),
      scene_(&scene),
      one_round_(options.use_64_bit_atomics && offers_64_bit_atomics()),
      capacity_(capacity_for(targets, options)),
      chunk_capacity_(chunk_capacity_for(capacity_, options)),
      depth_keys_(create_buffer(pixel_count(targets) * (one_round_ ? sizeof(std::uint64_t) : sizeof(std::uint32_t)), nullptr)),
      winners_(one_round_ ? GlBuffer() : create_buffer(pixel_count(targets) * sizeof(std::uint32_t), nullptr)),
      large_triangles_(create_buffer(capacity_ * kLargeTriangleBytes, nullptr)),
      tile_chunks_(create_buffer(std::size_t{chunk_capacity_} * kTileChunkBytes, nullptr)),
      counters_(create_buffer(sizeof(Counters), nullptr)),
      reset_program_(ShaderProgram::from_embedded({"compute_visibility_reset.comp.glsl"}, raster_defines(one_round_))),
      triangle_program_(ShaderProgram::from_embedded({"compute_visibility_triangles.comp.glsl"}, raster_defines(one_round_))),
      large_program_(ShaderProgram::from_embedded({"compute_visibility_large.comp.glsl"}, raster_defines(one_round_))),
      chunk_dispatch_program_(ShaderProgram::from_embedded({"compute_visibility_chunk_dispatch.comp.glsl"})),
      tile_program_(ShaderProgram::from_embedded({"compute_visibility_tiles.comp.glsl"}, raster_defines(one_round_))),
      ids_program_(ShaderProgram::from_embedded({"compute_visibility_ids.comp.glsl"}, raster_defines(one_round_))),
      resolve_program_(ShaderProgram::from_embedded({"fullscreen.vert.glsl", "compute_visibility_resolve.frag.glsl"},
                                                    raster_defines(one_round_))),
      framebuffer_(create_framebuffer()),
      empty_vertex_array_(create_vertex_array()) {
  if (scene.instances().empty()) fail("compute visibility: the scene has no instances");
  const std::vector<std::uint32_t> first = instance_first_triangles(scene);
  triangle_count_ = first.back();
  instance_count_ = static_cast<std::uint32_t>(scene.instances().size());
  instance_first_triangle_ = create_buffer(std::span<const std::uint32_t>(first));
  deferred_ = create_buffer((triangle_count_ + 1) * sizeof(std::uint32_t), nullptr);
  if (!one_round_) {
    touched_ = create_buffer((triangle_count_ + 1) * sizeof(std::uint32_t), nullptr);
    clear_to(touched_, 0u);
  }

  set_uint(large_program_, "large_capacity", capacity_);
  for (ShaderProgram* program : {&large_program_, &chunk_dispatch_program_, &tile_program_})
    set_uint(*program, "chunk_capacity", chunk_capacity_);
  for (ShaderProgram* program : {&triangle_program_, &large_program_, &tile_program_, &ids_program_, &resolve_program_})
    set_uint(*program, "instance_count", instance_count_);
  set_uint(triangle_program_, "triangle_count", triangle_count_);
  const std::size_t pixels = pixel_count(targets);
  set_uint(reset_program_, "pixel_count", static_cast<std::uint32_t>(pixels));
  reset_groups_ = reset_groups(pixels);

  const GLuint fb = framebuffer_.id();
  glNamedFramebufferTexture(fb, GL_COLOR_ATTACHMENT0, targets.visibility_id.id(), 0);
  glNamedFramebufferTexture(fb, GL_DEPTH_ATTACHMENT, targets.depth.id(), 0);
  glNamedFramebufferDrawBuffer(fb, GL_COLOR_ATTACHMENT0);
  require_framebuffer_complete(framebuffer_, "compute visibility ids");
  check_gl("compute visibility set-up");
}

void ComputeVisibilityPass::run() {
  GlPassScope scope("compute_visibility");
  const RasterTargets& t = *targets_;
  scene_->bind_resources();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kDepthKeyBinding, depth_keys_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLargeTriangleBinding, large_triangles_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileChunkBinding, tile_chunks_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kCounterBinding, counters_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInstanceFirstTriangleBinding, instance_first_triangle_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kDeferredBinding, deferred_.id());
  if (!one_round_) {  // the one-round shaders declare neither winners nor touched
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kWinnerBinding, winners_.id());
    stamp_run();
  }
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, counters_.id());
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);  // the last run's readers of the buffers
  reset_program_.use();
  {
    GlPassScope stage("reset");
    glDispatchCompute(reset_groups_, 1, 1);
  }

  // One invocation per triangle; more groups than one dimension takes wrap into y.
  const GLuint groups = work_groups(triangle_count_, kTriangleGroupSize);
  const GLuint groups_x = std::min(groups, kMaxGroupsX);
  const GLuint groups_y = work_groups(groups, groups_x);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);  // the reset, and deformed vertices
  const auto set_round = [this](GLuint round) {
    for (ShaderProgram* program : {&triangle_program_, &large_program_, &tile_program_})
      set_uint(*program, "raster_round", round);
  };
  // Round 0: nearest depths, and the lists (each dispatch reads what the one before wrote).
  constexpr GLbitfield kStorageAndCommands = GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT;
  set_round(0);
  triangle_program_.use();
  { GlPassScope stage("triangles"); if (groups > 0) glDispatchCompute(groups_x, groups_y, 1); }
  glMemoryBarrier(kStorageAndCommands);
  large_program_.use();
  { GlPassScope stage("large"); glDispatchComputeIndirect(kDeferredDispatchOffset); }
  glMemoryBarrier(kStorageAndCommands);
  chunk_dispatch_program_.use();
  { GlPassScope stage("chunk_dispatch"); glDispatchCompute(1, 1, 1); }
  glMemoryBarrier(kStorageAndCommands);
  tile_program_.use();
  { GlPassScope stage("tiles"); glDispatchComputeIndirect(kTileDispatchOffset); }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  if (!one_round_) {
    // Round 1 over the same lists: the three dispatches only read the final depths and lower the
    // winners, so none waits for another.
    GlPassScope round1("round1");  // one scope: a stamp between would serialise them
    set_round(1);
    triangle_program_.use();
    if (groups > 0) glDispatchCompute(groups_x, groups_y, 1);
    large_program_.use();
    glDispatchComputeIndirect(kDeferredDispatchOffset);
    tile_program_.use();
    glDispatchComputeIndirect(kTileDispatchOffset);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);

  // The ids by a compute dispatch; the depth only when asked (write_depth).
  ids_program_.use();
  glBindImageTexture(0, t.visibility_id.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kVisibilityIdFormat);
  { GlPassScope stage("ids"); dispatch_over_image(t.width, t.height); }
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  check_gl("compute visibility");
}

void ComputeVisibilityPass::stamp_run() {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTouchedBinding, touched_.id());
  if (++run_stamp_ == 0) {  // after 2^32 runs: stamps of 0 are the cleared ones again
    clear_to(touched_, 0u);
    run_stamp_ = 1;
  }
  set_uint(triangle_program_, "run_stamp", run_stamp_);
}

void ComputeVisibilityPass::write_depth() const {
  GlPassScope scope("compute_visibility_depth");
  const RasterTargets& t = *targets_;
  scene_->bind_resources();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kDepthKeyBinding, depth_keys_.id());
  if (!one_round_) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kWinnerBinding, winners_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInstanceFirstTriangleBinding, instance_first_triangle_.id());
  // Ids and depth through the framebuffer the id draw would use: every pixel written, depth
  // test on so that depth is written, always passing.
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.id());
  glViewport(0, 0, t.width, t.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_BLEND);
  resolve_program_.use();
  glBindVertexArray(empty_vertex_array_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glDepthFunc(GL_LESS);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  check_gl("compute visibility: depth");
}

ComputeVisibilityStats ComputeVisibilityPass::read_stats() const {
  Counters counters;
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(counters_.id(), 0, sizeof(Counters), &counters);
  check_gl("compute visibility: read counters");
  return {counters.deferred_count, std::min(counters.large_count, capacity_),
          std::min(counters.chunk_count, chunk_capacity_), counters.overflowed};
}

}  // namespace glint::render
