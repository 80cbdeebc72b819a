/// The core pixel sampler (pixel/pixel_sampler.hpp) in a CUDA kernel gives
/// the CPU's draws bit for bit (docs/pixel-sampling.md): one thread per pixel
/// of a 32 × 32 image starts each of its samples and draws the film position,
/// a 2D value, a 1D value and a 4-point array, for every device-ready
/// technique, in frame 0 and frame 3. Without a CUDA device it prints SKIPPED
/// and why, and exits 77 (ctest's SKIP_RETURN_CODE): a skip, never a pass.
#include <cuda_runtime.h>

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "device_present.hpp"
#include "stratum/pixel/pixel_sampler.hpp"
#include "stratum/pixel/set_techniques.hpp"

namespace {

using namespace stratum::pixel;

constexpr unsigned side = 32, spp = 8, array_count = 4;
constexpr unsigned values_per_sample = 2 + 2 + 1 + 2 * array_count;

/// What one pixel's samples draw, in order, into out (values_per_sample a sample).
template <class Technique>
__host__ __device__ void draw_pixel(const Shared<Technique>* shared, unsigned x, unsigned y, double* out) {
  PixelSampler<Technique> sampler(shared);
  for (unsigned i = 0; i < spp; ++i, out += values_per_sample) {
    sampler.start_pixel_sample(x, y, i);
    const auto film = sampler.get_pixel_2d();
    const auto lens = sampler.get_2d();
    out[0] = film[0], out[1] = film[1], out[2] = lens[0], out[3] = lens[1], out[4] = sampler.get_1d();
    std::array<double, 2> shadow[array_count];
    sampler.get_2d_array(array_count, shadow);
    for (unsigned k = 0; k < array_count; ++k) out[5 + 2 * k] = shadow[k][0], out[6 + 2 * k] = shadow[k][1];
  }
}

template <class Technique>
__global__ void draw_pixels(const Shared<Technique>* shared, double* out) {
  const unsigned pixel = blockIdx.x * blockDim.x + threadIdx.x;
  if (pixel >= side * side) return;
  draw_pixel(shared, pixel % side, pixel / side, out + std::size_t{pixel} * spp * values_per_sample);
}

void check(cudaError_t status, const char* what) {
  if (status == cudaSuccess) return;
  std::fprintf(stderr, "FAILED: %s: %s\n", what, cudaGetErrorString(status));
  std::exit(1);
}

/// A device copy of `count` values; freed at exit of the process.
template <class T>
T* to_device(const T* data, std::size_t count) {
  void* p = nullptr;
  check(cudaMalloc(&p, count * sizeof(T)), "cudaMalloc");
  check(cudaMemcpy(p, data, count * sizeof(T), cudaMemcpyHostToDevice), "cudaMemcpy to the device");
  return static_cast<T*>(p);
}

int failures = 0;

/// Draws `device_technique` (its tables in device memory) in a kernel and
/// `host_technique` on the CPU; counts the values whose bits differ.
template <class Technique>
void compare(const char* name, const Technique& device_technique, const Technique& host_technique) {
  for (const std::uint32_t frame : {0u, 3u}) {
    const auto device_shared = Shared<Technique>::make(device_technique, spp, 20261208, frame);
    const auto host_shared = Shared<Technique>::make(host_technique, spp, 20261208, frame);
    const std::size_t count = std::size_t{side} * side * spp * values_per_sample;
    std::vector<double> host(count), device(count);
    for (unsigned pixel = 0; pixel < side * side; ++pixel)
      draw_pixel(&*host_shared, pixel % side, pixel / side, host.data() + std::size_t{pixel} * spp * values_per_sample);
    double* out = nullptr;
    check(cudaMalloc(&out, count * sizeof(double)), "cudaMalloc");
    draw_pixels<<<(side * side + 127) / 128, 128>>>(to_device(&*device_shared, 1), out);
    check(cudaGetLastError(), "kernel launch");
    check(cudaDeviceSynchronize(), "kernel run");
    check(cudaMemcpy(device.data(), out, count * sizeof(double), cudaMemcpyDeviceToHost), "cudaMemcpy to the host");
    std::size_t differ = 0;
    for (std::size_t k = 0; k < count; ++k)
      differ += std::bit_cast<std::uint64_t>(host[k]) != std::bit_cast<std::uint64_t>(device[k]);
    std::printf("%-28s frame %u: %zu values, %zu differ\n", name, frame, count, differ);
    failures += differ != 0;
  }
}

}  // namespace

int main() {
  if (!stratum::cuda_testing::device_present("the pixel samplers", "cuda_pixel_ptx_check"))
    return stratum::cuda_testing::skip_exit_code;
  const stratum::Sobol& sobol = stratum::Sobol::first_two();
  const stratum::Sobol::View device_sobol = sobol.view([](const std::uint64_t* data, std::size_t count) {
    return static_cast<const std::uint64_t*>(to_device(data, count));
  });
  const auto sobol_pair = [&](auto technique) {
    auto on_device = technique;
    on_device.sobol = device_sobol;
    return std::pair{on_device, technique};
  };
  compare("random", RandomTechnique{}, RandomTechnique{});
  {
    const auto [d, h] = sobol_pair(SobolTechnique<base2_scrambles::None>{});
    compare("sobol:none", d, h);
  }
  {
    const auto [d, h] = sobol_pair(SobolOwenHash{});
    compare("sobol:owen-hash", d, h);
  }
  {
    const auto [d, h] = sobol_pair(SobolTechnique<base2_scrambles::Owen>{});
    compare("sobol:owen", d, h);
  }
  {
    const auto [d, h] = sobol_pair(SobolTechnique<base2_scrambles::Xor>{});
    compare("sobol:xor", d, h);
  }
  {
    const auto [d, h] = sobol_pair(SobolTechnique<base2_scrambles::Lms>{});
    compare("sobol:lms", d, h);
  }
  {
    const auto [d, h] = sobol_pair(SobolTechnique<base2_scrambles::Rotation>{});
    compare("sobol:cp", d, h);
  }
  compare("pmj02", Pmj02Technique{}, Pmj02Technique{});
  compare("halton:cp", HaltonTechnique{{}, true}, HaltonTechnique{{}, true});
  const KroneckerTechnique kronecker{Kronecker2D::of(stratum::Kronecker(2)), true};
  compare("kronecker:cp", kronecker, kronecker);
  compare("lattice-sequence:cp", LatticeSequenceTechnique{{}, true}, LatticeSequenceTechnique{{}, true});
  if (failures) std::printf("FAILED: %d comparisons differ\n", failures);
  else std::printf("all pixel samplers draw the CPU's values on the device\n");
  return failures ? 1 : 0;
}
