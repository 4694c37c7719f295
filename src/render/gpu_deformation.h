#pragma once
// --deform-on gpu: the scene's sine deformers run as CUDA kernels that write the frame pipeline's GL
// vertex buffer and, with a GPU ray tracer, its device positions (cuda/gpu_scene_deformer.h).
#include "cuda/gpu_scene_deformer.h"
#include "render/frame_pipeline.h"
#include "scene/sine_deformer.h"

#include <memory>

namespace glint::render {

// `deformers` and `pipeline` must outlive the result. glint::Error without a CUDA GPU, or when the
// pipeline traces rays with a CPU backend (its structures are built from host vertices, which the
// GPU deformer does not touch).
std::unique_ptr<cuda::GpuSceneDeformer> make_gpu_deformer(const SceneDeformers& deformers, FramePipeline& pipeline);

}  // namespace glint::render
