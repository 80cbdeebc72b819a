/// The core's samplers and warps run in CUDA kernels and give the CPU's
/// numbers (docs/gpu.md). Each kernel fills points (or warps points) on the
/// device; the host computes the same with the same headers and compares:
///  - sequences (Sobol with none / owen-hash / lms / xor, Halton plain /
///    permute / owen, PMJ02, the rank-1 lattice): bit for bit;
///  - warps (polar and concentric disk, uniform and cosine hemisphere):
///    pdfs bit for bit; sample and invert within 4 ulp, because they call
///    sin, cos and atan2, which neither CUDA's library nor glibc rounds
///    correctly in every case (CUDA Programming Guide, "Mathematical
///    functions": 2 ulp for double sin, cos, atan2); the arithmetic around
///    them is compiled without contraction (--fmad=false) as the host's.
/// Without a CUDA device the program prints SKIPPED and why, and exits 77
/// (ctest's SKIP_RETURN_CODE): a skip, never a pass.
#include <cuda_runtime.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <span>
#include <vector>

#include "device_present.hpp"
#include "stratum/randomizers/base2.hpp"
#include "stratum/randomizers/digit_permutation.hpp"
#include "stratum/randomizers/owen_base_b.hpp"
#include "stratum/sequences/halton.hpp"
#include "stratum/sequences/lattice.hpp"
#include "stratum/sequences/pmj.hpp"
#include "stratum/sequences/sobol.hpp"
#include "stratum/warps/disk.hpp"
#include "stratum/warps/sphere.hpp"

namespace {

constexpr unsigned block_size = 128;

/// Sobol with a base-2 randomizer, as the registry composes it.
template <class Randomizer>
struct RandomizedSobol {
  stratum::Sobol::View sobol;
  Randomizer randomizer;
  __host__ __device__ double sample(std::uint64_t index, unsigned dim) const {
    return sobol.sample(index, dim, randomizer);
  }
};

/// out[i·dims + d] = sampler.sample(first + i, d): the dimension is a run-time
/// value (what made Halton's kernel a trap when its tables were host-only).
template <class Sampler>
__global__ void fill_points(Sampler sampler, std::uint64_t first, unsigned count, unsigned dims, double* out) {
  const unsigned i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= count) return;
  for (unsigned d = 0; d < dims; ++d) out[std::size_t{i} * dims + d] = sampler.sample(first + i, d);
}

/// The warps of one 2D point u (and of the directions and disk points the
/// host computed from it, for pdf and invert), 18 values per point.
__global__ void warp_points(const double* u, const double* disk_points, const double* directions, unsigned count,
                            double* out) {
  const unsigned i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= count) return;
  const std::array<double, 2> v = {u[2 * i], u[2 * i + 1]};
  const std::array<double, 2> p = {disk_points[2 * i], disk_points[2 * i + 1]};
  const std::array<double, 3> w = {directions[3 * i], directions[3 * i + 1], directions[3 * i + 2]};
  double* o = out + std::size_t{i} * 18;
  const auto polar = stratum::sample_polar_disk(v);
  const auto concentric = stratum::sample_concentric_disk(v);
  const auto hemisphere = stratum::sample_uniform_hemisphere(v);
  const auto cosine = stratum::sample_cosine_hemisphere(v);
  const auto polar_back = stratum::invert_polar_disk(p);
  const auto concentric_back = stratum::invert_concentric_disk(p);
  const auto hemisphere_back = stratum::invert_uniform_hemisphere(w);
  o[0] = polar[0], o[1] = polar[1], o[2] = concentric[0], o[3] = concentric[1];
  o[4] = hemisphere[0], o[5] = hemisphere[1], o[6] = hemisphere[2];
  o[7] = cosine[0], o[8] = cosine[1], o[9] = cosine[2];
  o[10] = polar_back[0], o[11] = polar_back[1], o[12] = concentric_back[0], o[13] = concentric_back[1];
  o[14] = hemisphere_back[0], o[15] = hemisphere_back[1];
  o[16] = stratum::concentric_disk_pdf(p) + stratum::polar_disk_pdf(p);
  o[17] = stratum::uniform_hemisphere_pdf(w) + stratum::cosine_hemisphere_pdf(w);
}

/// Copies host arrays to the device for the samplers' views; frees them at the end.
class DeviceArrays {
 public:
  DeviceArrays() = default;
  DeviceArrays(const DeviceArrays&) = delete;
  DeviceArrays& operator=(const DeviceArrays&) = delete;
  ~DeviceArrays() {
    for (void* p : owned_) cudaFree(p);
  }
  template <class T>
  T* operator()(const T* data, std::size_t count) {
    void* p = nullptr;
    if (count == 0) return nullptr;
    check(cudaMalloc(&p, count * sizeof(T)), "cudaMalloc");
    owned_.push_back(p);
    check(cudaMemcpy(p, data, count * sizeof(T), cudaMemcpyHostToDevice), "cudaMemcpy to the device");
    return static_cast<T*>(p);
  }
  double* output(std::size_t count) {
    void* p = nullptr;
    check(cudaMalloc(&p, count * sizeof(double)), "cudaMalloc");
    owned_.push_back(p);
    return static_cast<double*>(p);
  }
  static void check(cudaError_t status, const char* what) {
    if (status == cudaSuccess) return;
    std::fprintf(stderr, "FAILED: %s: %s\n", what, cudaGetErrorString(status));
    std::exit(1);
  }

 private:
  std::vector<void*> owned_;
};

std::vector<double> copy_back(const double* device, std::size_t count) {
  std::vector<double> host(count);
  DeviceArrays::check(cudaMemcpy(host.data(), device, count * sizeof(double), cudaMemcpyDeviceToHost),
                      "cudaMemcpy to the host");
  return host;
}

/// Distance in units in the last place between two finite doubles.
std::uint64_t ulp_distance(double a, double b) {
  const auto ordered = [](double x) {
    const auto bits = std::bit_cast<std::int64_t>(x);
    return bits < 0 ? std::numeric_limits<std::int64_t>::min() - bits : bits;
  };
  const std::int64_t x = ordered(a), y = ordered(b);
  return x > y ? static_cast<std::uint64_t>(x - y) : static_cast<std::uint64_t>(y - x);
}

int failures = 0;
int comparisons = 0;

/// Runs fill_points on the device and compares with sampler_cpu bit for bit.
template <class DeviceSampler, class HostSampler>
void compare_points(const char* name, const DeviceSampler& device_sampler, const HostSampler& host_sampler,
                    DeviceArrays& arrays, std::uint64_t first, unsigned count, unsigned dims) {
  double* out = arrays.output(std::size_t{count} * dims);
  fill_points<<<(count + block_size - 1) / block_size, block_size>>>(device_sampler, first, count, dims, out);
  DeviceArrays::check(cudaGetLastError(), "kernel launch");
  DeviceArrays::check(cudaDeviceSynchronize(), "kernel run");
  const std::vector<double> device = copy_back(out, std::size_t{count} * dims);
  std::size_t mismatches = 0;
  for (unsigned i = 0; i < count; ++i)
    for (unsigned d = 0; d < dims; ++d) {
      const double host = host_sampler.sample(first + i, d);
      const double got = device[std::size_t{i} * dims + d];
      if (std::bit_cast<std::uint64_t>(host) != std::bit_cast<std::uint64_t>(got)) {
        if (mismatches++ < 5)
          std::printf("  %s: point %llu dim %u: device %.17g, host %.17g\n", name,
                      static_cast<unsigned long long>(first + i), d, got, host);
      }
    }
  std::printf("%-24s %8u points x %3u dims from index %llu: %zu mismatches\n", name, count, dims,
              static_cast<unsigned long long>(first), mismatches);
  ++comparisons;
  if (mismatches) ++failures;
}

void compare_warps(DeviceArrays& arrays) {
  constexpr unsigned count = 1 << 14;
  const stratum::Sobol sobol(2);
  std::vector<double> u(2 * count), disk_points(2 * count), directions(3 * count), host(18 * std::size_t{count});
  for (unsigned i = 0; i < count; ++i) {
    const std::array<double, 2> v = {sobol.sample(i, 0), sobol.sample(i, 1)};
    u[2 * i] = v[0], u[2 * i + 1] = v[1];
    const auto p = stratum::sample_concentric_disk(v);
    const auto w = stratum::sample_cosine_hemisphere(v);
    disk_points[2 * i] = p[0], disk_points[2 * i + 1] = p[1];
    directions[3 * i] = w[0], directions[3 * i + 1] = w[1], directions[3 * i + 2] = w[2];
    const auto polar = stratum::sample_polar_disk(v);
    const auto hemisphere = stratum::sample_uniform_hemisphere(v);
    const auto polar_back = stratum::invert_polar_disk(p);
    const auto concentric_back = stratum::invert_concentric_disk(p);
    const auto hemisphere_back = stratum::invert_uniform_hemisphere(w);
    double* o = host.data() + std::size_t{i} * 18;
    o[0] = polar[0], o[1] = polar[1], o[2] = p[0], o[3] = p[1];
    o[4] = hemisphere[0], o[5] = hemisphere[1], o[6] = hemisphere[2];
    o[7] = w[0], o[8] = w[1], o[9] = w[2];
    o[10] = polar_back[0], o[11] = polar_back[1], o[12] = concentric_back[0], o[13] = concentric_back[1];
    o[14] = hemisphere_back[0], o[15] = hemisphere_back[1];
    o[16] = stratum::concentric_disk_pdf(p) + stratum::polar_disk_pdf(p);
    o[17] = stratum::uniform_hemisphere_pdf(w) + stratum::cosine_hemisphere_pdf(w);
  }
  double* out = arrays.output(host.size());
  warp_points<<<(count + block_size - 1) / block_size, block_size>>>(
      arrays(u.data(), u.size()), arrays(disk_points.data(), disk_points.size()),
      arrays(directions.data(), directions.size()), count, out);
  DeviceArrays::check(cudaGetLastError(), "kernel launch");
  DeviceArrays::check(cudaDeviceSynchronize(), "kernel run");
  const std::vector<double> device = copy_back(out, host.size());
  constexpr std::uint64_t max_ulps = 4;
  std::size_t beyond = 0, inexact_pdf = 0, differing = 0;
  std::uint64_t worst = 0;
  for (std::size_t k = 0; k < host.size(); ++k) {
    const std::uint64_t ulps = ulp_distance(host[k], device[k]);
    const bool pdf = k % 18 >= 16;
    // Values near 0 (a coordinate of a point on an axis) carry the absolute
    // error of their neighbours; compare those against 2^-52 absolutely.
    const bool close = ulps <= max_ulps || std::abs(host[k] - device[k]) <= 0x1.0p-52;
    differing += ulps != 0;
    worst = std::max(worst, ulps);
    if (pdf ? ulps != 0 : !close) {
      if ((pdf ? inexact_pdf : beyond) < 5)
        std::printf("  warps: value %zu of point %zu: device %.17g, host %.17g (%llu ulp)\n", k % 18, k / 18, device[k],
                    host[k], static_cast<unsigned long long>(ulps));
      ++(pdf ? inexact_pdf : beyond);
    }
  }
  std::printf("%-24s %8u points: %zu values differ (largest %llu ulp), %zu beyond %llu ulp, %zu pdfs not exact\n",
              "warps", count, differing, static_cast<unsigned long long>(worst), beyond,
              static_cast<unsigned long long>(max_ulps), inexact_pdf);
  ++comparisons;
  if (beyond || inexact_pdf) ++failures;
}

}  // namespace

int main() {
  if (!stratum::cuda_testing::device_present("the kernels", "cuda_ptx_check"))
    return stratum::cuda_testing::skip_exit_code;

  DeviceArrays arrays;
  constexpr unsigned count = 1 << 14;
  const std::uint64_t seed = 20260101;
  const std::uint64_t far = (std::uint64_t{1} << 40) + 12345;  // indices past 2^32

  const stratum::Sobol sobol(64);
  const stratum::Sobol::View sobol_device = sobol.view(arrays);
  const stratum::Sobol::View sobol_host = sobol.view();
  for (const std::uint64_t first : {std::uint64_t{0}, far}) {
    compare_points("sobol", RandomizedSobol<stratum::NoRandomizer>{sobol_device, {}},
                   RandomizedSobol<stratum::NoRandomizer>{sobol_host, {}}, arrays, first, count, 64);
    const stratum::HashOwenScrambler owen(seed);
    compare_points("sobol:owen-hash", RandomizedSobol<stratum::HashOwenScrambler>{sobol_device, owen},
                   RandomizedSobol<stratum::HashOwenScrambler>{sobol_host, owen}, arrays, first, count, 64);
    const stratum::LinearMatrixScramble lms(seed);
    compare_points("sobol:lms", RandomizedSobol<stratum::LinearMatrixScramble>{sobol_device, lms},
                   RandomizedSobol<stratum::LinearMatrixScramble>{sobol_host, lms}, arrays, first, count, 64);
    const stratum::DigitalShift shift(seed);
    compare_points("sobol:xor", RandomizedSobol<stratum::DigitalShift>{sobol_device, shift},
                   RandomizedSobol<stratum::DigitalShift>{sobol_host, shift}, arrays, first, count, 64);
  }

  constexpr unsigned halton_dims = 64;
  std::vector<std::uint32_t> bases(halton_dims);
  for (unsigned d = 0; d < halton_dims; ++d) bases[d] = stratum::Halton::base(d);
  const stratum::Halton halton(stratum::Halton::max_dimensions);
  // Indices up to 2^20 use the permutation tables, larger ones the slow path.
  const stratum::RandomDigitPermutations permute(seed, bases, std::uint64_t{1} << 20);
  const stratum::BaseBOwenScrambler owen_b(seed, bases);
  for (const std::uint64_t first : {std::uint64_t{0}, far}) {
    compare_points("halton", halton, halton, arrays, first, count, stratum::Halton::max_dimensions);
    compare_points("halton:permute", permute.view(arrays), permute.view(), arrays, first, count, halton_dims);
    compare_points("halton:owen", owen_b.view(arrays), owen_b.view(), arrays, first, count, halton_dims);
    const stratum::Pmj02 pmj(stratum::Pmj02::max_dimensions, seed);
    compare_points("pmj02", pmj, pmj, arrays, first, count, stratum::Pmj02::max_dimensions);
  }

  const stratum::KorobovSearch search(1021, 8);
  const auto generator = stratum::korobov_generator(1021, search.best(), 8);
  const stratum::Rank1Lattice lattice(1021, std::span<const std::uint64_t>(generator.data(), 8));
  compare_points("lattice", lattice, lattice, arrays, 0, 1021, 8);
  const stratum::Rank1Lattice fibonacci = stratum::fibonacci_lattice(832040);
  compare_points("lattice (fibonacci)", fibonacci, fibonacci, arrays, far, count, 2);

  compare_warps(arrays);

  if (failures) std::printf("FAILED: %d of %d comparisons differ\n", failures, comparisons);
  else std::printf("all %d comparisons equal\n", comparisons);
  return failures ? 1 : 0;
}
