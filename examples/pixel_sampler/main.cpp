// The core pixel sampler in a renderer of one's own (docs/pixel-sampling.md).
//
// The "scene" is an edge: the half-plane cos(θ)·x + sin(θ)·y ≤ c over a
// 64 × 64 image. A pixel's value is the fraction of its area inside the
// half-plane, known exactly (the unit square clipped by the line); the
// renderer estimates it from spp film positions of the pixel sampler and
// prints the mean squared error over the image for each technique. A
// technique is chosen once, by a template argument: the draws are one path.
//
//   pixel_sampler_example [spp]      (default 16; a square for jittered and cmj)
#include <stratum/pixel/pixel_sampler.hpp>
#include <stratum/pixel/set_techniques.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

constexpr int size = 64;
constexpr double pi = 3.14159265358979323846;
const double normal_x = std::cos(0.3 * pi), normal_y = std::sin(0.3 * pi), offset = 40.0;

bool inside(double x, double y) { return normal_x * x + normal_y * y <= offset; }

/// The exact area of pixel (px, py) inside the half-plane: the pixel's square
/// clipped by the line (Sutherland–Hodgman against one edge), then the shoelace formula.
double exact_coverage(int px, int py) {
  const std::array<std::array<double, 2>, 4> square{
      {{double(px), double(py)}, {px + 1.0, double(py)}, {px + 1.0, py + 1.0}, {double(px), py + 1.0}}};
  std::vector<std::array<double, 2>> clipped;
  const auto side = [](const std::array<double, 2>& p) { return normal_x * p[0] + normal_y * p[1] - offset; };
  for (std::size_t i = 0; i < square.size(); ++i) {
    const auto& a = square[i];
    const auto& b = square[(i + 1) % square.size()];
    const double sa = side(a), sb = side(b);
    if (sa <= 0) clipped.push_back(a);
    if ((sa < 0 && sb > 0) || (sa > 0 && sb < 0)) {
      const double t = sa / (sa - sb);
      clipped.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
    }
  }
  double twice_area = 0;
  for (std::size_t i = 0; i < clipped.size(); ++i) {
    const auto& a = clipped[i];
    const auto& b = clipped[(i + 1) % clipped.size()];
    twice_area += a[0] * b[1] - a[1] * b[0];
  }
  return std::abs(twice_area) / 2;
}

/// The image's mean squared error with `technique` at spp samples a pixel,
/// averaged over `renders` seeds; negative where it cannot make spp points.
template <class Technique>
double mean_squared_error(const Technique& technique, std::uint32_t spp, int renders) {
  double sum = 0;
  for (int render = 0; render < renders; ++render) {
    const auto shared = stratum::pixel::Shared<Technique>::make(technique, spp, std::uint64_t(render));
    if (!shared) return -1;
    stratum::pixel::PixelSampler<Technique> sampler(&*shared);  // 32 bytes: one per thread or GPU lane
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        double hits = 0;
        for (std::uint32_t i = 0; i < spp; ++i) {
          sampler.start_pixel_sample(std::uint32_t(x), std::uint32_t(y), i);
          const auto film = sampler.get_pixel_2d();
          hits += inside(x + film[0], y + film[1]) ? 1.0 : 0.0;
        }
        const double error = hits / spp - exact_coverage(x, y);
        sum += error * error;
      }
  }
  return sum / (double(renders) * size * size);
}

template <class Technique>
void report(const char* name, const Technique& technique, std::uint32_t spp, double baseline) {
  const double mse = mean_squared_error(technique, spp, 8);
  if (mse < 0) return (void)std::printf("%-22s  (takes no set of %u points)\n", name, spp);
  std::printf("%-22s  %.3e  %6.1fx\n", name, mse, baseline / mse);
}

}  // namespace

int main(int argc, char** argv) {
  const long spp = argc > 1 ? std::strtol(argv[1], nullptr, 10) : 16;
  if (spp < 1 || spp > 65536) return std::fprintf(stderr, "spp: %s: must be in [1, 65536]\n", argv[1]), 2;
  using namespace stratum::pixel;
  const auto n = std::uint32_t(spp);
  const double random = mean_squared_error(RandomTechnique{}, n, 8);
  std::printf("edge coverage of a %dx%d image at %u spp: MSE over 8 renders, and random's / the technique's\n", size,
              size, n);
  report("random", RandomTechnique{}, n, random);
  report("jittered", JitteredTechnique{}, n, random);
  report("cmj", CmjTechnique{}, n, random);
  report("sobol (owen-hash)", SobolOwenHash{}, n, random);
  report("sobol (owen)", SobolTechnique<base2_scrambles::Owen>{}, n, random);
  report("pmj02", Pmj02Technique{}, n, random);
  report("halton (cp)", HaltonTechnique{{}, true}, n, random);
  report("lattice-sequence (cp)", LatticeSequenceTechnique{{}, true}, n, random);
  // Stratification must pay on an edge: every stratified technique beats random.
  const double stratified = mean_squared_error(SobolOwenHash{}, n, 8);
  return n >= 16 && !(stratified < random) ? 1 : 0;
}
