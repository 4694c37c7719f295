#version 450 core
// After the ray list of `--reflections auto` (RayListPass with a tile list): keeps the count the
// list asked for (rays_wanted, for timings.csv) and cuts the list's count to the budget. The list
// pass wrote no ray at or past max_rays, so the first max_rays slots are exactly the listed rays.
layout(local_size_x = 1) in;

layout(std430, binding = 9) buffer RayCounters { uint ray_count; uint reflective_count; };
layout(std430, binding = 23) buffer TileDispatch { uint dispatch_words[18]; };  // render::TileDispatchBlock

uniform int max_rays;  // >= 0

const uint kRaysWantedWord = 14u;

void main() {
  dispatch_words[kRaysWantedWord] = ray_count;
  ray_count = min(ray_count, uint(max_rays));
}
