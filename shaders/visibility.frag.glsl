#version 450 core
// Visibility buffer, surface (VisibilityIdPass): writes the visible triangle's id and nothing else
// (depth comes from the rasteriser). Id texel (RG32UI, kVisibilityIdFormat): x = instance + 1
// (0 = background), y = the triangle's number in its mesh (gl_PrimitiveID counts from 0 in each
// draw command, and each command draws one instance's whole mesh from its first index).
layout(early_fragment_tests) in;

flat in uint instance;

layout(location = 0) out uvec2 visibility_id;

void main() { visibility_id = uvec2(instance + 1u, uint(gl_PrimitiveID)); }
