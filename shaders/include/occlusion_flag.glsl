// The occlusion query's answers (OcclusionBuffers, src/render/occlusion_buffers.h) at storage
// binding 11: one uint per ray from a GPU backend (trace_any_device), one byte per ray from a CPU
// backend (trace_any's uint8_t span), four to a uint, the first in the low byte. The includer sets
// `occlusion_flag_bytes` to OcclusionBuffers::flag_bytes().
layout(std430, binding = 11) readonly buffer Occluded { uint occluded_words[]; };

uniform int occlusion_flag_bytes;  // 4 or 1

// Whether ray i of the list found an occluder.
bool occluded(uint i) {
  if (occlusion_flag_bytes == 4) return occluded_words[i] != 0u;
  return ((occluded_words[i >> 2u] >> (8u * (i & 3u))) & 0xFFu) != 0u;
}
