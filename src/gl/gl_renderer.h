#pragma once
// Which OpenGL implementation the current context runs on, for the choices that depend on it.
#include <string>
#include <string_view>

namespace glint {

// GL_RENDERER of the current context ("NVIDIA H100 80GB HBM3/PCIe/SSE2", "llvmpipe (LLVM 15.0.6,
// 256 bits)"); "" when no context is current.
std::string current_gl_renderer();

// Whether `gl_renderer` (a GL_RENDERER string) names one of Mesa's software rasterisers (llvmpipe,
// softpipe): the GPU is the CPU there, its timer queries mean nothing and some shader paths cost far
// more than on hardware (gpu_timer.h, visibility_gbuffer_pass.cpp).
bool software_gl_renderer(std::string_view gl_renderer);

}  // namespace glint
