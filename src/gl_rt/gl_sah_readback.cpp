#include "gl_rt/gl_sah_readback.h"

#include <algorithm>
#include <cstring>

namespace glint::gl_rt {

void GlSahReadback::reset(std::size_t mesh_count) {
  const std::size_t bytes = std::max<std::size_t>(mesh_count, 1) * sizeof(double);
  ring_.emplace(kFramesInFlight, bytes, "rt gl: SAH costs");
  costs_ = create_buffer(bytes, nullptr, 0);
  slots_.assign(kFramesInFlight, {});
  latest_.assign(mesh_count, std::nullopt);
  latest_sequence_.assign(mesh_count, 0);
  generation_.assign(mesh_count, 0);
  measurements_ = 0;
}

bool GlSahReadback::measure(GlSahCost& sah, const GlStructureBuffers& structures,
                            std::span<const std::uint32_t> meshes, const accel::SahCosts& costs) {
  if (meshes.empty()) return true;
  const std::size_t slot = static_cast<std::size_t>(measurements_ % slots_.size());
  if (slots_[slot].in_flight) {
    if (!ring_->ready(slot)) return false;
    take(slot, ring_->read(slot, false));
  }
  sah.measure(structures, meshes, costs, costs_.id());
  ring_->copy_buffer(slot, costs_.id(), meshes.size() * sizeof(double));
  Pending& pending = slots_[slot];
  pending.meshes.assign(meshes.begin(), meshes.end());
  pending.generations.clear();
  for (const std::uint32_t mesh : meshes) pending.generations.push_back(generation_[mesh]);
  pending.sequence = ++measurements_;
  pending.in_flight = true;
  return true;
}

void GlSahReadback::collect() {
  for (std::size_t slot = 0; slot < slots_.size(); ++slot)
    if (slots_[slot].in_flight && ring_->ready(slot)) take(slot, ring_->read(slot, false));
}

void GlSahReadback::take(std::size_t slot, std::span<const std::byte> bytes) {
  Pending& pending = slots_[slot];
  pending.in_flight = false;
  for (std::size_t i = 0; i < pending.meshes.size(); ++i) {
    const std::uint32_t mesh = pending.meshes[i];
    // Measured before a rebuild, or older than what is known: skipped.
    if (pending.generations[i] != generation_[mesh] || pending.sequence < latest_sequence_[mesh]) continue;
    double cost = 0.0;
    std::memcpy(&cost, bytes.data() + i * sizeof(double), sizeof(double));
    latest_[mesh] = cost;
    latest_sequence_[mesh] = pending.sequence;
  }
}

void GlSahReadback::forget(std::uint32_t mesh) {
  ++generation_[mesh];
  latest_[mesh] = std::nullopt;
}

}  // namespace glint::gl_rt
