#include "render/tile_classify_pass.h"

#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"
#include "render/reflection_texture_check.h"
#include "render/render_targets.h"

#include <cstring>

namespace glint::render {
namespace {

constexpr GLuint kAlbedoUnit = 0, kPositionUnit = 1, kPreviousMaskUnit = 2, kPreviousOutcomeUnit = 3,
                 kOutcomeUnit = 4, kReflectionUnit = 5;
constexpr GLenum kOutcomeFormat = GL_R8UI;
// The ray list starts this many entries into the list buffer: 64 uints = 256 bytes, the largest
// GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT drivers ask for.
constexpr std::size_t kListAlignmentEntries = 64;

std::size_t evidence_bytes(std::size_t tiles) { return tiles * 4 * sizeof(std::uint32_t); }

}  // namespace

TileClassifyPass::TileClassifyPass(int width, int height)
    : program_(ShaderProgram::from_embedded({"tile_classify.comp.glsl"})),
      width_(width),
      height_(height),
      columns_(render::tile_columns(width)),
      rows_(render::tile_rows(height)),
      ray_list_offset_(0),
      block_readback_(kFramesInFlight, sizeof(TileDispatchBlock), "tile dispatch block"),
      evidence_readback_(kFramesInFlight, evidence_bytes(static_cast<std::size_t>(render::tile_columns(width)) *
                                                         static_cast<std::size_t>(render::tile_rows(height))),
                         "tile evidence") {
  require_pass_size("tile classification", width, height);
  const std::size_t tiles = tile_count();
  ray_list_offset_ = (tiles + kListAlignmentEntries - 1) / kListAlignmentEntries * kListAlignmentEntries;
  for (int i = 0; i < 2; ++i) {
    outcome_[static_cast<std::size_t>(i)] = create_texture_2d(kOutcomeFormat, width, height);
    const std::vector<std::uint32_t> zero(tiles * 4, 0u);
    evidence_[static_cast<std::size_t>(i)] =
        create_buffer(std::span<const std::uint32_t>(zero), GL_DYNAMIC_STORAGE_BIT);
  }
  lists_ = create_buffer((ray_list_offset_ + tiles) * sizeof(std::uint32_t), nullptr, GL_DYNAMIC_STORAGE_BIT);
  dispatch_ = create_buffer(sizeof(TileDispatchBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
  program_.set_uniform("tile_columns", columns_);
  program_.set_uniform("ray_list_offset", static_cast<int>(ray_list_offset_));
  check_gl("tile classification: set-up");
}

void TileClassifyPass::run(const TileClassifyInputs& inputs, const TileThresholds& thresholds,
                           std::optional<TileClass> every_tile) {
  GlPassScope scope("classify");
  require_texture("tile classification", "albedo_reflectivity", inputs.albedo_reflectivity, kAlbedoReflectivityFormat,
                  width_, height_);
  require_texture("tile classification", "world_position", inputs.world_position, kWorldPositionFormat, width_,
                  height_);
  require_texture("tile classification", "previous_failure_mask", inputs.previous_failure_mask, kFailureMaskFormat,
                  width_, height_);
  require_texture("tile classification", "reflection", inputs.reflection, kReflectionFormat, width_, height_);
  const int previous = current_;
  current_ ^= 1;
  const auto cur = static_cast<std::size_t>(current_), prev = static_cast<std::size_t>(previous);

  TileDispatchBlock block{};
  block.ssr_groups[1] = block.ssr_groups[2] = 1;
  block.ray_groups[1] = block.ray_groups[2] = 1;
  glNamedBufferSubData(dispatch_.id(), 0, sizeof(block), &block);

  glBindImageTexture(kAlbedoUnit, inputs.albedo_reflectivity, 0, GL_FALSE, 0, GL_READ_ONLY, kAlbedoReflectivityFormat);
  glBindImageTexture(kPositionUnit, inputs.world_position, 0, GL_FALSE, 0, GL_READ_ONLY, kWorldPositionFormat);
  glBindImageTexture(kPreviousMaskUnit, inputs.previous_failure_mask, 0, GL_FALSE, 0, GL_READ_ONLY,
                     kFailureMaskFormat);
  glBindImageTexture(kPreviousOutcomeUnit, outcome_[prev].id(), 0, GL_FALSE, 0, GL_READ_ONLY, kOutcomeFormat);
  glBindImageTexture(kOutcomeUnit, outcome_[cur].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kOutcomeFormat);
  glBindImageTexture(kReflectionUnit, inputs.reflection, 0, GL_FALSE, 0, GL_WRITE_ONLY, kReflectionFormat);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileListBinding, lists_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileEvidenceBinding, evidence_[cur].id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPreviousTileEvidenceBinding, evidence_[prev].id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileDispatchBinding, dispatch_.id());
  program_.set_uniform("previous_view_projection", previous_view_projection_);
  program_.set_uniform("have_history", have_history_ ? 1 : 0);
  program_.set_uniform("ssr_only_at_most", thresholds.ssr_only_at_most);
  program_.set_uniform("rt_at_least", thresholds.rt_at_least);
  program_.set_uniform("min_known_fraction", thresholds.min_known_fraction);
  program_.set_uniform("forced_class", every_tile ? static_cast<int>(*every_tile) : -1);
  program_.use();
  glDispatchCompute(static_cast<GLuint>(columns_), static_cast<GLuint>(rows_), 1);
  // SSR and the ray list read the lists (storage) and sizes (indirect); SSR overwrites the reflection.
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                  GL_BUFFER_UPDATE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  previous_view_projection_ = inputs.view_projection;
  have_history_ = true;
  check_gl("tile classification");
}

TileListDispatch TileClassifyPass::ssr_tiles() const {
  return {lists_.id(), 0, static_cast<GLsizeiptr>(tile_count() * sizeof(std::uint32_t)), dispatch_.id(),
          kSsrIndirectOffset, columns_};
}

TileListDispatch TileClassifyPass::ray_tiles() const {
  return {lists_.id(), static_cast<GLintptr>(ray_list_offset_ * sizeof(std::uint32_t)),
          static_cast<GLsizeiptr>(tile_count() * sizeof(std::uint32_t)), dispatch_.id(), kRayIndirectOffset, columns_};
}

void TileClassifyPass::request_readback(std::size_t slot) {
  block_readback_.copy_buffer(slot, dispatch_.id(), sizeof(TileDispatchBlock));
  evidence_readback_.copy_buffer(slot, evidence_[static_cast<std::size_t>(current_)].id(),
                                 evidence_bytes(tile_count()));
}

bool TileClassifyPass::readback_ready(std::size_t slot) {
  return block_readback_.ready(slot) && evidence_readback_.ready(slot);
}

std::optional<TileFrameReadback> TileClassifyPass::take(std::size_t slot, bool wait) {
  const std::span<const std::byte> block = block_readback_.read(slot, wait);
  if (block.empty()) return std::nullopt;
  const std::span<const std::byte> evidence = evidence_readback_.read(slot, wait);
  if (evidence.empty()) return std::nullopt;
  return decode(block.data(), evidence.data());
}

TileFrameReadback TileClassifyPass::read() const {
  std::vector<std::byte> block(sizeof(TileDispatchBlock)), evidence(evidence_bytes(tile_count()));
  glGetNamedBufferSubData(dispatch_.id(), 0, static_cast<GLsizeiptr>(block.size()), block.data());
  glGetNamedBufferSubData(evidence_[static_cast<std::size_t>(current_)].id(), 0,
                          static_cast<GLsizeiptr>(evidence.size()), evidence.data());
  check_gl("tile classification: read back");
  return decode(block.data(), evidence.data());
}

TileFrameReadback TileClassifyPass::decode(const std::byte* block, const std::byte* evidence) const {
  TileFrameReadback result;
  std::memcpy(&result.block, block, sizeof(TileDispatchBlock));
  std::vector<std::uint32_t> words(tile_count() * 4);
  std::memcpy(words.data(), evidence, words.size() * sizeof(std::uint32_t));
  result.tiles.resize(tile_count());
  result.classes.resize(tile_count());
  for (std::size_t i = 0; i < tile_count(); ++i) {
    result.tiles[i] = {words[4 * i], words[4 * i + 1], words[4 * i + 2]};
    result.classes[i] = static_cast<TileClass>(words[4 * i + 3] & 3u);
  }
  return result;
}

}  // namespace glint::render
