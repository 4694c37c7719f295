#version 450 core
// SSR's march alone (SsrPass::march), before lighting: the trusted hits for ssr_colour.comp.glsl
// (include/ssr_march.glsl).
layout(local_size_x = 8, local_size_y = 8) in;
const bool kColourInMarch = false;
#include "include/ssr_march.glsl"
