#include "optix/trace_pipeline.h"

#include "optix/embedded_optix_modules.h"
#include "optix/result_check.h"

#include <optix_stack_size.h>
#include <optix_stubs.h>

#include <array>
#include <cstring>
#include <span>

namespace glint::optix {
namespace {

constexpr unsigned int kPayloadValues = 5;    // t, instance, prim, u, v
constexpr unsigned int kAttributeValues = 2;  // the triangle's barycentrics
constexpr unsigned int kMaxTraceDepth = 1;    // raygen traces; nothing traces recursively
constexpr unsigned int kTraversableDepth = 2; // IAS -> GAS (or one GAS alone)

// Each SBT record is a header only: the programs read nothing per record.
constexpr std::size_t kRecordStride =
    (OPTIX_SBT_RECORD_HEADER_SIZE + OPTIX_SBT_RECORD_ALIGNMENT - 1) / OPTIX_SBT_RECORD_ALIGNMENT * OPTIX_SBT_RECORD_ALIGNMENT;

OptixPipelineCompileOptions pipeline_compile_options(bool validation) {
  OptixPipelineCompileOptions options{};
  options.usesMotionBlur = 0;
  options.traversableGraphFlags = OPTIX_TRAVERSABLE_GRAPH_FLAG_ALLOW_ANY;  // IAS (render) or GAS (accel-bench)
  options.numPayloadValues = static_cast<int>(kPayloadValues);
  options.numAttributeValues = static_cast<int>(kAttributeValues);
  options.exceptionFlags = validation ? OPTIX_EXCEPTION_FLAG_STACK_OVERFLOW | OPTIX_EXCEPTION_FLAG_TRACE_DEPTH
                                      : OPTIX_EXCEPTION_FLAG_NONE;
  options.pipelineLaunchParamsVariableName = kLaunchParamsName;
  options.usesPrimitiveTypeFlags = static_cast<unsigned int>(OPTIX_PRIMITIVE_TYPE_FLAGS_TRIANGLE);
  return options;
}

bool same_params(const OptixLaunchParams& a, const OptixLaunchParams& b) {
  return a.root == b.root && a.rays == b.rays && a.hits == b.hits && a.occluded == b.occluded &&
         a.ray_count == b.ray_count && a.capacity == b.capacity;
}

}  // namespace

TraceClosestPipeline::TraceClosestPipeline(OptixDeviceContext context, bool validation) {
  const OptixPipelineCompileOptions compile = pipeline_compile_options(validation);
  char log[4096];
  std::size_t log_size = sizeof(log);

  OptixModuleCompileOptions module_options{};
  module_options.maxRegisterCount = OPTIX_COMPILE_DEFAULT_MAX_REGISTER_COUNT;
  module_options.optLevel = validation ? OPTIX_COMPILE_OPTIMIZATION_LEVEL_0 : OPTIX_COMPILE_OPTIMIZATION_DEFAULT;
  module_options.debugLevel = validation ? OPTIX_COMPILE_DEBUG_LEVEL_MINIMAL : OPTIX_COMPILE_DEBUG_LEVEL_NONE;
  const std::span<const unsigned char> code = embedded_optix_module("trace_closest_programs");
  GLINT_OPTIX_CHECK_LOG(optixModuleCreate(context, &module_options, &compile, reinterpret_cast<const char*>(code.data()),
                                          code.size(), log, &log_size, &module_),
                        log, log_size);

  OptixProgramGroupOptions group_options{};
  std::array<OptixProgramGroupDesc, 3> descs{};
  descs[0].kind = OPTIX_PROGRAM_GROUP_KIND_RAYGEN;
  descs[0].raygen.module = module_;
  descs[0].raygen.entryFunctionName = "__raygen__trace_closest";
  descs[1].kind = OPTIX_PROGRAM_GROUP_KIND_MISS;
  descs[1].miss.module = module_;
  descs[1].miss.entryFunctionName = "__miss__no_hit";
  descs[2].kind = OPTIX_PROGRAM_GROUP_KIND_HITGROUP;
  descs[2].hitgroup.moduleCH = module_;
  descs[2].hitgroup.entryFunctionNameCH = "__closesthit__triangle";
  std::array<OptixProgramGroup, 3> groups{};
  log_size = sizeof(log);
  GLINT_OPTIX_CHECK_LOG(optixProgramGroupCreate(context, descs.data(), static_cast<unsigned int>(descs.size()),
                                                &group_options, log, &log_size, groups.data()),
                        log, log_size);
  raygen_ = groups[0];
  miss_ = groups[1];
  hit_group_ = groups[2];

  OptixPipelineLinkOptions link{};
  link.maxTraceDepth = kMaxTraceDepth;
  log_size = sizeof(log);
  GLINT_OPTIX_CHECK_LOG(optixPipelineCreate(context, &compile, &link, groups.data(),
                                            static_cast<unsigned int>(groups.size()), log, &log_size, &pipeline_),
                        log, log_size);

  // Stack sizes from the programs' own needs (no callables, no recursion).
  OptixStackSizes stack{};
  for (OptixProgramGroup group : groups) GLINT_OPTIX_CHECK(optixUtilAccumulateStackSizes(group, &stack, pipeline_));
  unsigned int from_traversal = 0, from_state = 0, continuation = 0;
  GLINT_OPTIX_CHECK(optixUtilComputeStackSizes(&stack, kMaxTraceDepth, 0, 0, &from_traversal, &from_state, &continuation));
  GLINT_OPTIX_CHECK(optixPipelineSetStackSize(pipeline_, from_traversal, from_state, continuation, kTraversableDepth));

  std::array<std::byte, 3 * kRecordStride> records{};
  GLINT_OPTIX_CHECK(optixSbtRecordPackHeader(raygen_, records.data()));
  GLINT_OPTIX_CHECK(optixSbtRecordPackHeader(miss_, records.data() + kRecordStride));
  GLINT_OPTIX_CHECK(optixSbtRecordPackHeader(hit_group_, records.data() + 2 * kRecordStride));
  sbt_records_.upload(std::span<const std::byte>(records));
  const auto base = reinterpret_cast<CUdeviceptr>(sbt_records_.data());
  sbt_.raygenRecord = base;
  sbt_.missRecordBase = base + kRecordStride;
  sbt_.missRecordStrideInBytes = static_cast<unsigned int>(kRecordStride);
  sbt_.missRecordCount = 1;
  sbt_.hitgroupRecordBase = base + 2 * kRecordStride;
  sbt_.hitgroupRecordStrideInBytes = static_cast<unsigned int>(kRecordStride);
  sbt_.hitgroupRecordCount = 1;
}

TraceClosestPipeline::~TraceClosestPipeline() {
  // Not checked: runs in a destructor.
  if (pipeline_) optixPipelineDestroy(pipeline_);
  for (OptixProgramGroup group : {raygen_, miss_, hit_group_})
    if (group) optixProgramGroupDestroy(group);
  if (module_) optixModuleDestroy(module_);
}

void TraceClosestPipeline::launch(const OptixLaunchParams& params, cudaStream_t stream) {
  if (params.capacity == 0) return;
  // The pointers are the same frame after frame (the GL buffers shared with CUDA), so the
  // parameters are uploaded only when they change.
  ParamsSlot& slot = params_[params.occluded != nullptr ? 1 : 0];
  if (!slot.uploaded || !same_params(params, slot.last)) {
    slot.device.upload(std::span<const OptixLaunchParams>(&params, 1), stream);
    slot.last = params;
    slot.uploaded = true;
  }
  GLINT_OPTIX_CHECK(optixLaunch(pipeline_, stream, reinterpret_cast<CUdeviceptr>(slot.device.device()),
                                sizeof(OptixLaunchParams), &sbt_, params.capacity, 1, 1));
}

}  // namespace glint::optix
