// Every GpuScene buffer at once (bindings 1..5: vertices, indices, mesh_ranges, instances,
// materials), for passes such as hit shading that read the whole scene. Passes that read only some
// buffers include the smaller files instead, so they declare no buffer they do not use.
#include "include/scene_geometry.glsl"
#include "include/scene_instances.glsl"
#include "include/scene_materials.glsl"
