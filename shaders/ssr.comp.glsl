#version 450 core
// SSR in one dispatch (SsrPass::run): the march of include/ssr_march.glsl, fetching each trusted
// hit's colour from the lit image as it goes.
layout(local_size_x = 8, local_size_y = 8) in;
const bool kColourInMarch = true;
#include "include/ssr_march.glsl"
