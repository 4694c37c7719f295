#pragma once
// The gl backend's automatic update policy reads the SAH cost of its GPU-refitted BLASes without
// stalling a frame (GlRayTracer::update_gl, docs/ray-tracer.md "gl"): each update's measurement
// (GlSahCost) is copied into a slot of a readback ring (gl/readback_ring.h) behind the update's own
// GPU work, and later updates take the slots the GPU has finished (a fence checked with a zero
// timeout). So an update decides on a cost measured one or more updates before it (on a GPU typically
// two or three, kFramesInFlight slots), never on one it would have to wait for; where every slot is
// still in flight, that update's measurement is skipped rather than waited for.
//
// A rebuilt BLAS forgets its cost: the measurements of its old BVH, taken or still in flight, say
// nothing about the new one.
#include "gl/gl_objects.h"
#include "gl/readback_ring.h"
#include "gl_rt/gl_sah_cost.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace glint::gl_rt {

class GlSahReadback {
public:
  // Forgets everything and makes room for the costs of `mesh_count` meshes; needs the GL context.
  void reset(std::size_t mesh_count);

  // Enqueues `sah`'s measurement of `meshes` (just refitted on the GPU) and its copy into the next
  // slot. Returns false, measuring nothing, when that slot's copy is still in flight.
  bool measure(GlSahCost& sah, const GlStructureBuffers& structures, std::span<const std::uint32_t> meshes,
               const accel::SahCosts& costs);
  // Takes the costs of every slot the GPU has finished (never waits).
  void collect();
  // The latest cost collected for `mesh` since its last build; nullopt when none.
  std::optional<double> cost(std::uint32_t mesh) const { return latest_[mesh]; }
  // `mesh` was rebuilt: its earlier measurements, collected or in flight, no longer apply.
  void forget(std::uint32_t mesh);

private:
  // A slot's measurement: which meshes, in order, and each one's build generation when measured.
  struct Pending {
    std::vector<std::uint32_t> meshes;
    std::vector<std::uint64_t> generations;
    std::uint64_t sequence = 0;  // the measurement's number: a later one's costs win
    bool in_flight = false;
  };
  void take(std::size_t slot, std::span<const std::byte> bytes);

  std::optional<ReadbackRing> ring_;
  GlBuffer costs_;  // the kernel's output, copied into a slot
  std::vector<Pending> slots_;
  std::vector<std::optional<double>> latest_;
  std::vector<std::uint64_t> latest_sequence_;  // the measurement latest_ came from
  std::vector<std::uint64_t> generation_;       // per mesh: its rebuilds
  std::uint64_t measurements_ = 0;
};

}  // namespace glint::gl_rt
