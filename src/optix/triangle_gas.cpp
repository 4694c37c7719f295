#include "optix/triangle_gas.h"

#include "core/error.h"
#include "optix/result_check.h"

#include <optix_stubs.h>

#include <algorithm>
#include <limits>

namespace glint::optix {
namespace {

// Opaque triangles: the closest hit is all the query needs, and no any-hit program exists.
const unsigned int kGeometryFlags[1] = {OPTIX_GEOMETRY_FLAG_DISABLE_ANYHIT};

CUdeviceptr device_address(const void* pointer) { return reinterpret_cast<CUdeviceptr>(pointer); }

void ensure_scratch(cuda::DeviceBuffer<std::byte>& scratch, std::size_t bytes) {
  if (scratch.size() < bytes) scratch.resize(bytes);
}

}  // namespace

unsigned int gas_build_flags(BuildPreference preference, bool compact, bool allow_update) {
  unsigned int flags = preference == BuildPreference::fast_trace ? OPTIX_BUILD_FLAG_PREFER_FAST_TRACE
                                                                          : OPTIX_BUILD_FLAG_PREFER_FAST_BUILD;
  if (compact && preference == BuildPreference::fast_trace) flags |= OPTIX_BUILD_FLAG_ALLOW_COMPACTION;
  if (allow_update) flags |= OPTIX_BUILD_FLAG_ALLOW_UPDATE;
  return flags;
}

void TriangleGas::set_geometry(std::span<const vec3> positions, std::span<const std::uint32_t> indices) {
  constexpr std::size_t kMax = std::numeric_limits<std::uint32_t>::max();
  if (indices.empty() ? positions.size() % 3 != 0 : indices.size() % 3 != 0)
    fail("OptiX GAS: {} {} do not make whole triangles", indices.empty() ? positions.size() : indices.size(),
         indices.empty() ? "gathered positions" : "indices");
  if (positions.size() > kMax || indices.size() / 3 > kMax)
    fail("OptiX GAS: {} vertices, {} triangles exceed OptiX's 32-bit counts", positions.size(), indices.size() / 3);
  positions_.upload(positions);
  indices_.upload(indices);
  triangle_count_ = indices.empty() ? positions.size() / 3 : indices.size() / 3;
  built_ = false;
}

void TriangleGas::upload_positions(std::span<const vec3> positions, cudaStream_t stream) {
  if (positions.size() != positions_.size())
    fail("OptiX GAS: {} new positions for a mesh of {} vertices", positions.size(), positions_.size());
  if (positions.empty()) return;
  GLINT_CUDA_CHECK(cudaMemcpyAsync(positions_.data(), positions.data(), positions.size_bytes(), cudaMemcpyHostToDevice,
                                   stream));
}

OptixBuildInput TriangleGas::build_input() const {
  vertex_pointer_ = device_address(positions_.data());
  OptixBuildInput input{};
  input.type = OPTIX_BUILD_INPUT_TYPE_TRIANGLES;
  OptixBuildInputTriangleArray& triangles = input.triangleArray;
  triangles.vertexBuffers = &vertex_pointer_;
  triangles.numVertices = static_cast<unsigned int>(positions_.size());
  triangles.vertexFormat = OPTIX_VERTEX_FORMAT_FLOAT3;
  triangles.vertexStrideInBytes = sizeof(vec3);
  if (!indices_.empty()) {
    triangles.indexBuffer = device_address(indices_.data());
    triangles.numIndexTriplets = static_cast<unsigned int>(triangle_count_);
    triangles.indexFormat = OPTIX_INDICES_FORMAT_UNSIGNED_INT3;
    triangles.indexStrideInBytes = 3 * sizeof(std::uint32_t);
  }
  triangles.flags = kGeometryFlags;
  triangles.numSbtRecords = 1;
  return input;
}

OptixAccelBufferSizes TriangleGas::buffer_sizes(OptixDeviceContext context, unsigned int flags) const {
  const OptixBuildInput input = build_input();
  OptixAccelBuildOptions options{};
  options.buildFlags = flags;
  options.operation = OPTIX_BUILD_OPERATION_BUILD;
  OptixAccelBufferSizes sizes{};
  GLINT_OPTIX_CHECK(optixAccelComputeMemoryUsage(context, &options, &input, 1, &sizes));
  return sizes;
}

void TriangleGas::reserve_output(std::size_t bytes) {
  if (output_.size() < bytes) {
    output_.resize(bytes);
    built_ = false;  // a grown buffer lost the old structure
  }
}

void TriangleGas::build(OptixDeviceContext context, unsigned int flags, cuda::DeviceBuffer<std::byte>& scratch,
                        cudaStream_t stream, std::uint64_t* compacted_size) {
  const OptixAccelBufferSizes sizes = buffer_sizes(context, flags);
  reserve_output(sizes.outputSizeInBytes);
  ensure_scratch(scratch, sizes.tempSizeInBytes);
  const OptixBuildInput input = build_input();
  OptixAccelBuildOptions options{};
  options.buildFlags = flags;
  options.operation = OPTIX_BUILD_OPERATION_BUILD;
  OptixAccelEmitDesc emit{};
  emit.type = OPTIX_PROPERTY_TYPE_COMPACTED_SIZE;
  emit.result = device_address(compacted_size);
  GLINT_OPTIX_CHECK(optixAccelBuild(context, stream, &options, &input, 1, device_address(scratch.data()),
                                    scratch.size(), device_address(output_.data()), output_.size(), &handle_,
                                    compacted_size ? &emit : nullptr, compacted_size ? 1u : 0u));
  flags_ = flags;
  built_ = true;
}

void TriangleGas::update(OptixDeviceContext context, cuda::DeviceBuffer<std::byte>& scratch, cudaStream_t stream) {
  if (!built_) fail("OptiX GAS: update before build");
  if (!updatable()) fail("OptiX GAS: update of a structure built without OPTIX_BUILD_FLAG_ALLOW_UPDATE");
  const OptixAccelBufferSizes sizes = buffer_sizes(context, flags_);
  ensure_scratch(scratch, sizes.tempUpdateSizeInBytes);
  const OptixBuildInput input = build_input();
  OptixAccelBuildOptions options{};
  options.buildFlags = flags_;  // an update takes the flags of the build it updates
  options.operation = OPTIX_BUILD_OPERATION_UPDATE;
  GLINT_OPTIX_CHECK(optixAccelBuild(context, stream, &options, &input, 1, device_address(scratch.data()),
                                    scratch.size(), device_address(output_.data()), output_.size(), &handle_, nullptr,
                                    0));
}

void TriangleGas::compact(OptixDeviceContext context, std::size_t compacted_bytes, cudaStream_t stream) {
  if (!built_) fail("OptiX GAS: compaction before build");
  if (compacted_bytes == 0 || compacted_bytes >= output_.size()) return;  // nothing to gain
  cuda::DeviceBuffer<std::byte> compacted(compacted_bytes);
  GLINT_OPTIX_CHECK(optixAccelCompact(context, stream, handle_, device_address(compacted.data()), compacted.size(),
                                      &handle_));
  GLINT_CUDA_CHECK(cudaStreamSynchronize(stream));  // the copy has read the old buffer before it is freed
  output_ = std::move(compacted);
}

bool TriangleGas::updatable() const { return (flags_ & OPTIX_BUILD_FLAG_ALLOW_UPDATE) != 0; }

}  // namespace glint::optix
