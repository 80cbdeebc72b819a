/// Registry entries: the ranked blue-noise pixel samplers sobol-bn, pmj02-bn
/// and lattice-bn (sequences/ranked_blue_noise.hpp), one pixel's spp samples
/// per request.
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "families.hpp"
#include "stratum/sequences/ranked_blue_noise.hpp"
#include "stratum/util/error.hpp"
#include "support.hpp"

namespace stratum::registry_families {

using namespace registry_support;

namespace {

/// The rank tile of a base: the committed default, or the `table` file (of that base).
std::shared_ptr<const BlueNoiseTable> ranked_table(const SamplerRequest& request, BlueNoiseBase base) {
  if (!request.values.has("table") || request.values.text("table").empty())
    return {std::shared_ptr<const BlueNoiseTable>{}, &default_blue_noise_table(base)};
  const std::string& path = request.values.text("table");
  std::ifstream in(path, std::ios::binary);
  require(in.good(), "table", path, "cannot be read (give a file written by stratum optimize blue-noise)");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto table = std::make_shared<const BlueNoiseTable>(parse_blue_noise_table(bytes, path));
  require(table->base == base, "table", path,
          std::string("is a tile of base ") + blue_noise_base_name(table->base) + "; " + blue_noise_base_name(base) +
              "-bn needs one of base " + blue_noise_base_name(base) + " (stratum optimize blue-noise --base " +
              blue_noise_base_name(base) + ")");
  return table;
}

std::array<std::uint32_t, 2> ranked_pixel(const SamplerRequest& request) {
  const std::vector<std::int64_t>& pixel = request.values.integers("pixel");
  for (std::int64_t c : pixel)
    require(c >= 0 && c <= 0xffffffffLL, "pixel", std::to_string(pixel[0]) + "," + std::to_string(pixel[1]),
            "coordinates must be in [0, 2^32)");
  return {static_cast<std::uint32_t>(pixel[0]), static_cast<std::uint32_t>(pixel[1])};
}

PointSet generate_ranked(const SamplerRequest& request, BlueNoiseBase base) {
  const auto table = ranked_table(request, base);
  const auto [x, y] = ranked_pixel(request);
  const RankedBlueNoise sampler(*table, *request.n, request.seed);
  std::vector<RankedBlueNoise::PixelPair> pairs;
  for (unsigned p = 0; p < (request.d + 1) / 2; ++p) pairs.push_back(sampler.pixel_pair(x, y, p));
  return fill_index_addressable(*request.n, request.d, request.threads, [&](std::uint64_t i, unsigned j) {
    return sampler.point(request.start + i, pairs[j / 2])[j % 2];
  });
}

struct RankedEntry {
  BlueNoiseBase base;
  const char* base_description;  ///< the shared sequence, for the description
  std::vector<std::string> properties;
};

SamplerInfo ranked_entry(const RankedEntry& e) {
  const std::string name = std::string(blue_noise_base_name(e.base)) + "-bn";
  const BlueNoiseBase base = e.base;
  return {
      .name = name,
      .kind = "pattern",
      .description =
          std::string("the spp samples of one pixel of a blue-noise-error image sampler (after Heitz et al. 2019, "
                      "Belcour & Heitz 2021; OpenQMC's ") +
          (base == BlueNoiseBase::sobol   ? "SobolBn"
           : base == BlueNoiseBase::pmj02 ? "PmjBn"
                                          : "LatticeBn") +
          "): one " + e.base_description +
          " per dimension pair shared by the image, each pixel taking the block of spp points its rank in an "
          "optimized tile names (stratum optimize blue-noise --base " +
          blue_noise_base_name(base) + "; after the tile's dimensions, a per-pixel randomization); render --sampler " +
          name + " uses it per pixel",
      .min_dim = 1,
      .max_dim = blue_noise_max_dims(base),
      .flags = {.frames_continue = true, .self_randomized = true},
      .properties = e.properties,
      .randomization = {RandomizerFamily::seeded_owen_hash, Randomizer::owen_hash},
      .counts = "n = spp, 1 to 2^24 (powers of two give the base's 2^m-point structure per pixel)",
      .params = {params::integers("pixel", "the pixel x,y whose samples these are", "0,0", at_least(0), {2, 2}),
                 params::text("table",
                              std::string("a rank tile of base ") + blue_noise_base_name(base) +
                                  " written by stratum optimize blue-noise (default: the committed tile)",
                              "")},
      .validate =
          [base](const SamplerRequest& request) {
            const auto table = ranked_table(request, base);
            ranked_pixel(request);
            RankedBlueNoise(*table, *request.n, request.seed);  // checks n
          },
      .count = requested_count,
      .generate = [base](const SamplerRequest& request) { return generate_ranked(request, base); },
      .ranked_image = [base](const SamplerRequest& request) { return ranked_table(request, base); },
  };
}

}  // namespace

std::vector<SamplerInfo> blue_noise() {
  return {
      ranked_entry(
          {BlueNoiseBase::sobol,
           "Owen-scrambled Sobol' sequence",
           {"(0,m,2)-net per pixel in each dimension pair", "blue-noise error across pixels (the tile's dimensions)"}}),
      ranked_entry(
          {BlueNoiseBase::pmj02,
           "digital PMJ02 (0,2)-sequence (Helmer et al. 2021's generator matrices) under a hash-based Owen "
           "scramble, pmj02's kind of point sets,",
           {"(0,m,2)-net per pixel in each dimension pair", "blue-noise error across pixels (the tile's dimensions)"}}),
      ranked_entry({BlueNoiseBase::lattice,
                    "randomly shifted rank-1 lattice sequence (lattice's default generating vector)",
                    {"randomly shifted rank-1 lattice per pixel", "Latin in every coordinate per pixel",
                     "blue-noise error across pixels (the tile's dimensions)"}}),
  };
}

}  // namespace stratum::registry_families
