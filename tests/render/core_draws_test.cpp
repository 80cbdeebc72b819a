// The renderer's draws (render::PixelSampler) are the core pixel sampler's
// (pixel/pixel_sampler.hpp) for every core technique: pixel sets, get_1d,
// arrays and frames, so the renderer can draw through the core with its
// images unchanged. (Two implementations held equal: this goes when the
// renderer draws through the core.)
#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "stratum/pixel/pixel_sampler.hpp"
#include "stratum/pixel/set_techniques.hpp"
#include "stratum/render/pixel_sampler.hpp"

namespace {

using namespace stratum;
using namespace stratum::pixel;
using Points = std::vector<std::array<double, 2>>;

/// The renderer's draws for a spec against the core's for the technique.
template <class Technique>
void expect_renderer_draws(const Technique& technique, const std::string& sampler, const std::string& randomize,
                           std::uint32_t spp, std::uint32_t frame, std::uint32_t array_count) {
  SCOPED_TRACE(sampler + ":" + randomize + " frame " + std::to_string(frame));
  render::PixelSamplerSettings settings;
  settings.sampler = sampler, settings.randomize = randomize, settings.spp = spp, settings.seed = 5;
  settings.frame = frame;
  render::PixelSampler renderer(settings);
  const auto shared = *Shared<Technique>::make(technique, spp, 5, frame);
  PixelSampler<Technique> core(&shared);
  for (const auto& [x, y] : {std::pair{0u, 0u}, {7u, 3u}, {7u, 4u}, {1000u, 2u}})
    for (std::uint32_t i = 0; i < spp; ++i) {
      renderer.start_pixel_sample(x, y, i);
      core.start_pixel_sample(x, y, i);
      ASSERT_EQ(renderer.get_pixel_2d(), core.get_pixel_2d());
      ASSERT_EQ(renderer.get_1d(), core.get_1d());
      ASSERT_EQ(renderer.get_2d(), core.get_2d());
      Points a(array_count), b(array_count);
      renderer.get_2d_array(array_count, a.data());
      core.get_2d_array(array_count, b.data());
      ASSERT_EQ(a, b) << x << " " << y << " " << i;
      ASSERT_EQ(renderer.get_2d(), core.get_2d());
    }
}

TEST(CorePixelSampler, DrawsAreTheRenderersForEveryCoreTechnique) {
  for (const std::uint32_t frame : {0u, 2u}) {
    expect_renderer_draws(RandomTechnique{}, "random", "", 4, frame, 4);
    expect_renderer_draws(JitteredTechnique{}, "jittered", "", 4, frame, 9);
    expect_renderer_draws(SobolOwenHash{}, "sobol", "", 4, frame, 4);
    expect_renderer_draws(SobolTechnique<base2_scrambles::None>{}, "sobol", "none", 4, frame, 4);
    expect_renderer_draws(SobolTechnique<base2_scrambles::Owen>{}, "sobol", "owen", 4, frame, 4);
    expect_renderer_draws(SobolTechnique<base2_scrambles::Xor>{}, "sobol", "xor", 4, frame, 4);
    expect_renderer_draws(SobolTechnique<base2_scrambles::Lms>{}, "sobol", "lms", 4, frame, 4);
    expect_renderer_draws(SobolTechnique<base2_scrambles::Rotation>{}, "sobol", "cp", 4, frame, 4);
    expect_renderer_draws(SobolOwenHash{}, "zero-two", "", 8, frame, 2);
    expect_renderer_draws(Pmj02Technique{}, "pmj02", "", 4, frame, 4);
    expect_renderer_draws(HaltonTechnique{}, "halton", "none", 4, frame, 4);
    expect_renderer_draws(HaltonTechnique{{}, true}, "halton", "cp", 4, frame, 4);
    expect_renderer_draws(KroneckerTechnique{Kronecker2D::of(Kronecker(2)), true}, "kronecker", "cp", 4, frame, 4);
    expect_renderer_draws(LatticeSequenceTechnique{}, "lattice-sequence", "", 4, frame, 4);
    expect_renderer_draws(CmjTechnique{}, "cmj", "", 4, frame, 6);
  }
}

}  // namespace
