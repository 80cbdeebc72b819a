#pragma once
// Whether a CUDA device can run the kernels; if not, prints SKIPPED and why.
#include <cuda_runtime.h>

#include <cstdio>

namespace stratum::cuda_testing {

/// ctest's SKIP_RETURN_CODE: a skip, never a pass.
inline constexpr int skip_exit_code = 77;

/// True when device 0 exists (its name is printed); else prints SKIPPED, the
/// reason and which PTX check still ran, and returns false.
inline bool device_present(const char* kernels, const char* ptx_check) {
  int devices = 0;
  const cudaError_t status = cudaGetDeviceCount(&devices);
  if (status != cudaSuccess || devices == 0) {
    std::printf(
        "SKIPPED: no CUDA device to run %s on (cudaGetDeviceCount: %s, %d devices); "
        "the kernels were compiled and their PTX is checked by %s\n",
        kernels, status == cudaSuccess ? "no error" : cudaGetErrorString(status), devices, ptx_check);
    return false;
  }
  cudaDeviceProp properties{};
  if (cudaGetDeviceProperties(&properties, 0) == cudaSuccess)
    std::printf("device 0: %s (compute capability %d.%d)\n", properties.name, properties.major, properties.minor);
  return true;
}

}  // namespace stratum::cuda_testing
