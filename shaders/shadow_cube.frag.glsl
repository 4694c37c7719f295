#version 450 core
// Shadow cube map: depth = linear distance to the light / far distance, so ShadowMaskPass compares
// distances directly (a perspective depth would differ per face and be non-linear).

uniform vec3 light_position;
uniform float inverse_far_distance;

in vec3 world_position;

void main() { gl_FragDepth = length(world_position - light_position) * inverse_far_distance; }
