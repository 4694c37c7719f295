#version 450 core
// Writes one uniform colour to every covered pixel (clears with a shape, debug overlays, tests).

uniform vec4 color;

layout(location = 0) out vec4 frag_color;

void main() { frag_color = color; }
