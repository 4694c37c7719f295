#pragma once
// Which CUDA GPUs this machine has (empty when CUDA is off at build time or no GPU is present).
#include <cstddef>
#include <string>
#include <vector>

namespace glint {

struct CudaDeviceInfo {
  int index = 0;
  std::string name;
  int compute_capability = 0;  // e.g. 90 for sm_90
  std::size_t memory_bytes = 0;
  int driver_version = 0;      // e.g. 13000
};

// `why_none`, when given, receives the reason the list is empty.
std::vector<CudaDeviceInfo> query_cuda_devices(std::string* why_none = nullptr);

// True when glint was built with CUDA and a CUDA GPU is usable now (GPU tests skip otherwise).
bool cuda_gpu_present();

// Throws one clear glint::Error, "<what> needs a CUDA GPU: <reason>", when there is none.
void require_cuda_gpu(const char* what);

}  // namespace glint
