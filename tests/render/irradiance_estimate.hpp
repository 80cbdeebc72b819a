#pragma once
/// The irradiance estimator of one light, for the light-sampling tests:
/// mean and standard error of L cos θ_x / p over `samples` samples of
/// scene.lights[0] from x (unit normal n), with uniform01(seed, i, ·) inputs.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "stratum/render/lights.hpp"
#include "stratum/util/hash.hpp"

namespace stratum::render::testing_support {

inline std::pair<double, double> irradiance(const Scene& scene, Vec3 x, Vec3 n, LightStrategy strategy, int samples,
                                            std::uint64_t seed) {
  double sum = 0, sum2 = 0;
  for (int i = 0; i < samples; ++i) {
    const auto s =
        sample_light(scene, scene.lights[0], x, n, 0, {uniform01(seed, i, 0), uniform01(seed, i, 1)}, strategy);
    const double v = s ? s->radiance.x * std::max(0.0, dot(n, s->wi)) / s->pdf : 0.0;
    sum += v, sum2 += v * v;
  }
  const double mean = sum / samples;
  return {mean, std::sqrt(std::max(0.0, sum2 / samples - mean * mean) / (samples - 1))};
}

}  // namespace stratum::render::testing_support
