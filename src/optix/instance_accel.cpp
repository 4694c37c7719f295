#include "optix/instance_accel.h"

#include "optix/result_check.h"

#include <optix_stubs.h>

namespace glint::optix {

OptixInstance make_instance(const mat4& transform, unsigned int index, OptixTraversableHandle gas) {
  OptixInstance instance{};
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 4; ++column) instance.transform[4 * row + column] = transform[column][row];
  instance.instanceId = index;
  instance.sbtOffset = 0;  // one hit group for everything
  instance.visibilityMask = 255;
  instance.flags = OPTIX_INSTANCE_FLAG_DISABLE_TRIANGLE_FACE_CULLING | OPTIX_INSTANCE_FLAG_DISABLE_ANYHIT;
  instance.traversableHandle = gas;
  return instance;
}

void InstanceAccel::build(OptixDeviceContext context, std::span<const OptixInstance> instances,
                          unsigned int build_flags, cuda::DeviceBuffer<std::byte>& scratch, cudaStream_t stream) {
  instances_.upload(instances, stream);
  OptixBuildInput input{};
  input.type = OPTIX_BUILD_INPUT_TYPE_INSTANCES;
  input.instanceArray.instances = reinterpret_cast<CUdeviceptr>(instances_.device());
  input.instanceArray.numInstances = static_cast<unsigned int>(instances.size());
  OptixAccelBuildOptions options{};
  options.buildFlags = build_flags;
  options.operation = OPTIX_BUILD_OPERATION_BUILD;
  OptixAccelBufferSizes sizes{};
  GLINT_OPTIX_CHECK(optixAccelComputeMemoryUsage(context, &options, &input, 1, &sizes));
  // Same instance count every update, so these grow at the first build only.
  if (output_.size() < sizes.outputSizeInBytes) output_.resize(sizes.outputSizeInBytes);
  if (scratch.size() < sizes.tempSizeInBytes) scratch.resize(sizes.tempSizeInBytes);
  GLINT_OPTIX_CHECK(optixAccelBuild(context, stream, &options, &input, 1, reinterpret_cast<CUdeviceptr>(scratch.data()),
                                    scratch.size(), reinterpret_cast<CUdeviceptr>(output_.data()), output_.size(),
                                    &handle_, nullptr, 0));
}

}  // namespace glint::optix
