// The renderer's pbrt-style sampler over the registry (src/render/pixel_sampler.cpp).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "stratum/randomizers/digit_permutation.hpp"
#include "stratum/render/pixel_sampler.hpp"
#include "stratum/sequences/ranked_blue_noise.hpp"
#include "stratum/util/error.hpp"
#include "../sequences/zero_net.hpp"

namespace stratum::render {
namespace {

PixelSamplerSettings settings(std::string sampler, std::uint32_t spp, std::string time = "") {
  PixelSamplerSettings s;
  s.sampler = std::move(sampler);
  s.spp = spp;
  s.seed = 7;
  s.time_pattern = std::move(time);
  return s;
}

/// Is each of the m×m strata of [0,1)² hit exactly once?
bool one_per_stratum(const std::vector<std::array<double, 2>>& points, int m) {
  std::set<int> cells;
  for (auto p : points) cells.insert(int(p[0] * m) * m + int(p[1] * m));
  return int(cells.size()) == m * m && int(points.size()) == m * m;
}

TEST(PixelSampler, EachDimensionOfAPixelIsAStratifiedSet) {
  PixelSampler sampler(settings("jittered", 16));
  std::vector<std::array<double, 2>> film, lens;
  for (std::uint32_t i = 0; i < 16; ++i) {
    sampler.start_pixel_sample(3, 5, i);
    film.push_back(sampler.get_pixel_2d());
    lens.push_back(sampler.get_2d());
  }
  EXPECT_TRUE(one_per_stratum(film, 4));
  EXPECT_TRUE(one_per_stratum(lens, 4));
  EXPECT_NE(film, lens);  // dimensions are independent sets
}

TEST(PixelSampler, ReplaysBitForBitInAnyOrder) {
  PixelSampler a(settings("sobol", 8)), b(settings("sobol", 8));
  std::vector<double> forward, backward(8);
  for (std::uint32_t i = 0; i < 8; ++i) {
    a.start_pixel_sample(1, 2, i);
    forward.push_back(a.get_2d()[1] + a.get_1d());
  }
  for (std::uint32_t i = 8; i-- > 0;) {
    b.start_pixel_sample(9, 9, 0);  // another pixel in between
    b.get_2d();
    b.start_pixel_sample(1, 2, i);
    backward[i] = b.get_2d()[1] + b.get_1d();
  }
  EXPECT_EQ(forward, backward);
  // Another pixel gets another scramble.
  a.start_pixel_sample(2, 2, 0);
  EXPECT_NE(a.get_2d()[1] + a.get_1d(), forward[0]);
}

TEST(PixelSampler, ArraysAreStratifiedAmongThemselves) {
  PixelSampler sampler(settings("jittered", 4));
  sampler.start_pixel_sample(0, 0, 1);
  std::vector<std::array<double, 2>> shadow(16);
  sampler.get_2d_array(16, shadow.data());
  EXPECT_TRUE(one_per_stratum(shadow, 4));
  std::vector<std::array<double, 2>> again(16);
  sampler.start_pixel_sample(0, 0, 2);  // another eye sample: another set
  sampler.get_2d_array(16, again.data());
  EXPECT_NE(shadow, again);
}

TEST(PixelSampler, TimePatternsGiveOneSamplePerTimeSlot) {
  for (const char* pattern : {"random", "cook", "magic-square"}) {
    PixelSampler sampler(settings("random", 16, pattern));
    std::vector<std::array<double, 2>> film;
    std::set<int> slots;
    for (std::uint32_t i = 0; i < 16; ++i) {
      sampler.start_pixel_sample(4, 4, i);
      film.push_back(sampler.get_pixel_2d());
      slots.insert(int(sampler.get_time() * 16));
    }
    EXPECT_TRUE(one_per_stratum(film, 4)) << pattern;
    EXPECT_EQ(slots.size(), 16u) << pattern;
  }
}

TEST(PixelSampler, BadSettingsAreNamed) {
  auto message = [](PixelSamplerSettings s) {
    try {
      PixelSampler sampler(std::move(s));
    } catch (const invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(message(settings("nope", 4)).find("sampler"), std::string::npos);
  EXPECT_NE(message(settings("random", 0)).find("spp"), std::string::npos);
  EXPECT_NE(message(settings("random", 16, "sideways")).find("time-pattern"), std::string::npos);
  EXPECT_NE(message(settings("random", 8, "cook")).find("spp = 8"), std::string::npos);            // not m²
  EXPECT_NE(message(settings("random", 36, "magic-square")).find("spp = 36"), std::string::npos);  // m = 6
}

}  // namespace
}  // namespace stratum::render

namespace stratum::render {
namespace {

TEST(PixelSampler, FastPathsEqualTheRegistry) {
  for (const char* name : {"random", "sobol", "jittered", "pmj02"}) {
    const PixelSampler sampler(settings(name, 16));
    EXPECT_TRUE(sampler.direct()) << name;
    for (std::uint64_t seed : {0ull, 12345ull, 0xdeadbeefcafeull}) {
      const PointSet fast = sampler.draw_for_test(64, seed);
      SamplerRequest request;
      request.n = 64;
      request.d = 2;
      request.seed = seed;
      const PointSet reference = generate_points(name, request);
      for (std::size_t i = 0; i < 128; ++i) ASSERT_EQ(fast.data[i], reference.data[i]) << name << " " << i;
    }
  }
}

TEST(PixelSampler, PixelDrawsArePointsOfTheRegistrySetsOfTheirSeeds) {
  // What a pixel sample draws (1D, 2D and an array, pixels revisited after
  // others, so that the per-pixel caches of the hash chain and of halton's
  // permutations are exercised) is point `index` of the registry's set for
  // the seed hashed from (seed, pixel, dimension[, index]) with plain hash64.
  const auto registry_set = [](const char* name, std::uint64_t n, std::uint64_t seed) {
    SamplerRequest request;
    request.n = n;
    request.d = 2;
    request.seed = seed;
    return generate_points(name, request);
  };
  for (const char* name : {"random", "sobol", "jittered", "pmj02", "halton"}) {
    PixelSampler sampler(settings(name, 16));
    for (auto [x, y] : {std::pair{0u, 0u}, {5u, 3u}, {5u, 4u}, {0u, 0u}})
      for (std::uint32_t index : {0u, 3u, 15u, 7u}) {
        sampler.start_pixel_sample(x, y, index);
        const double t = sampler.get_1d();
        const auto p = sampler.get_2d();
        std::array<double, 2> array[9];
        sampler.get_2d_array(9, array);
        const auto q = sampler.get_pixel_2d();
        const PointSet s0 = registry_set(name, 16, PixelSampler::set_seed_for_test(7, x, y, 0));
        const PointSet s1 = registry_set(name, 16, PixelSampler::set_seed_for_test(7, x, y, 1));
        // A pattern's array is its own 9-point set; a progressive sampler's is
        // points 9·index … 9·index + 8 of one set per pixel and dimension.
        const bool continued = std::string(name) != "jittered";
        const std::uint32_t first = continued ? 9 * index : 0;
        const PointSet s2 = registry_set(
            name, first + 9,
            PixelSampler::array_seed_for_test(7, x, y, 2, continued ? PixelSampler::tag_continued : index));
        const PointSet s3 = registry_set(name, 16, PixelSampler::set_seed_for_test(7, x, y, 3));
        ASSERT_EQ(t, s0(index, 0)) << name;
        ASSERT_EQ(p[0], s1(index, 0)) << name;
        ASSERT_EQ(p[1], s1(index, 1)) << name;
        for (std::size_t i = 0; i < 9; ++i) {
          ASSERT_EQ(array[i][0], s2(first + i, 0)) << name << " " << i;
          ASSERT_EQ(array[i][1], s2(first + i, 1)) << name << " " << i;
        }
        ASSERT_EQ(q[0], s3(index, 0)) << name;
        ASSERT_EQ(q[1], s3(index, 1)) << name;
      }
  }
}

TEST(PixelSampler, AProgressiveSamplersArraysOverThePixelsSamplesAreOneNet) {
  // 4 samples × 4 shadow rays: each array an aligned block of 4 (a
  // (0,2,2)-net), the 16 together a (0,4,2)-net of the pixel's array
  // sequence; a pattern's arrays are fresh per sample (only each a set).
  for (const char* name : {"sobol", "pmj02", "jittered"}) {
    PixelSampler sampler(settings(name, 4));
    for (auto [x, y] : {std::pair{0u, 0u}, {6u, 2u}}) {
      std::vector<std::array<double, 2>> all;
      for (std::uint32_t index = 0; index < 4; ++index) {
        sampler.start_pixel_sample(x, y, index);
        sampler.get_2d();
        std::array<double, 2> array[4];
        sampler.get_2d_array(4, array);
        const std::vector<std::array<double, 2>> one(array, array + 4);
        if (std::string(name) != "jittered") {
          EXPECT_TRUE(stratum::testing::is_zero_net(one)) << name << " " << index;
        }
        all.insert(all.end(), one.begin(), one.end());
      }
      if (std::string(name) != "jittered") {
        EXPECT_TRUE(stratum::testing::is_zero_net(all)) << name;
      } else {
        EXPECT_FALSE(stratum::testing::is_zero_net(all)) << "jittered's arrays were expected independent";
      }
    }
  }
}

TEST(PixelSampler, HaltonSetsEqualTheRegistry) {
  for (const char* randomize : {"", "permute", "owen"}) {
    PixelSamplerSettings s = settings("halton", 16);
    s.randomize = randomize;
    const PixelSampler sampler(s);
    // Up to 2187 = 3^7 the default permute builds only what the points need
    // (every index in the first digit chunk of both bases); above, RandomDigitPermutations.
    for (std::uint64_t n : {1ull, 2ull, 3ull, 4ull, 16ull, 81ull, 100ull, 2048ull, 2187ull, 2188ull})
      for (std::uint64_t seed : {0ull, 12345ull, 0xdeadbeefcafeull}) {
        const PointSet drawn = sampler.draw_for_test(n, seed);
        SamplerRequest request;
        request.n = n;
        request.d = 2;
        request.seed = seed;
        request.randomize = randomize;
        const PointSet reference = generate_points("halton", request);
        for (std::size_t i = 0; i < 2 * n; ++i)
          ASSERT_EQ(drawn.data[i], reference.data[i]) << randomize << " " << n << " " << i;
      }
  }
}

TEST(PixelSampler, EverySamplerDrivesTheRendererOrIsRefusedWithTheReason) {
  // Every registry sampler at a count it takes: the space-time patterns are
  // refused, naming --time-pattern; every other one draws each dimension
  // pair from its registry set (the set's first two coordinates), in [0,1).
  int driven = 0;
  for (const SamplerInfo& info : samplers()) {
    const unsigned d = std::max(2u, info.min_dim);
    std::uint32_t spp = 0;
    for (std::uint32_t n : {16u, 64u}) {
      SamplerRequest request;
      request.n = n;
      request.d = d;
      try {
        validate_request(info, request);
        spp = n;
        break;
      } catch (const invalid_argument&) {
      }
    }
    ASSERT_NE(spp, 0u) << info.name << " takes none of the counts tried";
    if (info.flags.space_time) {
      try {
        PixelSampler sampler(settings(info.name, spp));
        ADD_FAILURE() << info.name << " is accepted as a pixel sampler";
      } catch (const invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("--time-pattern"), std::string::npos) << e.what();
      }
      continue;
    }
    PixelSampler sampler(settings(info.name, spp));
    ++driven;
    for (std::uint32_t index : {0u, spp - 1}) {
      sampler.start_pixel_sample(3, 2, index);
      const auto p = sampler.get_2d();
      std::array<double, 2> array[4];
      sampler.get_2d_array(4, array);
      for (double v : {p[0], p[1], array[0][0], array[3][1], sampler.get_1d()}) {
        EXPECT_GE(v, 0.0) << info.name;
        EXPECT_LT(v, 1.0) << info.name;
      }
      if (sampler.direct() || info.flags.frames_continue || info.name == "halton") continue;  // tested above
      SamplerRequest request;  // the registry's set of pixel (3, 2)'s dimension 0
      request.n = spp;
      request.d = d;
      request.seed = PixelSampler::set_seed_for_test(7, 3, 2, 0);
      const PointSet set = generate_points(info.name, request);
      EXPECT_EQ(p[0], set(index, 0)) << info.name;
      EXPECT_EQ(p[1], set(index, 1)) << info.name;
      // The shadow-ray array (dimension 1): a progressive sampler's points
      // 4·index … 4·index + 3 of the pixel's continued set (its generator
      // bound once per pixel), a pattern's own 4-point set of this sample.
      const bool continued = info.flags.progressive;
      SamplerRequest arrays;
      arrays.n = continued ? 4 * (index + 1) : 4;
      arrays.d = d;
      arrays.seed = PixelSampler::array_seed_for_test(7, 3, 2, 1, continued ? PixelSampler::tag_continued : index);
      const PointSet array_set = generate_points(info.name, arrays);
      const std::uint32_t first = continued ? 4 * index : 0;
      for (std::uint32_t i = 0; i < 4; ++i) {
        EXPECT_EQ(array[i][0], array_set(first + i, 0)) << info.name << " array point " << i;
        EXPECT_EQ(array[i][1], array_set(first + i, 1)) << info.name << " array point " << i;
      }
    }
  }
  EXPECT_GE(driven, 25);
  // latin-square (an orthogonal array of strength 2): a pixel's 16 samples
  // put one point in every cell of the 4 × 4 grid of each dimension pair.
  PixelSampler latin(settings("latin-square", 16));
  std::vector<std::array<double, 2>> points;
  for (std::uint32_t index = 0; index < 16; ++index) {
    latin.start_pixel_sample(1, 1, index);
    points.push_back(latin.get_2d());
  }
  EXPECT_TRUE(one_per_stratum(points, 4));
}

TEST(PixelSampler, ScreenSpaceSamplersComeFromTheRegistrysHooks) {
  // The pixel samplers whose start continues the pixel's sequence (zsobol,
  // the ranked blue-noise samplers) are drawn through the image sampler the
  // registry gives (SamplerInfo::zsobol_image or ranked_image), never chosen
  // by name: a new one without its hook would be drawn as a set per pixel.
  int screen = 0;
  for (const SamplerInfo& info : samplers()) {
    const bool hooked = static_cast<bool>(info.zsobol_image) || static_cast<bool>(info.ranked_image);
    EXPECT_EQ(hooked, info.flags.frames_continue) << info.name;
    EXPECT_FALSE(info.zsobol_image && info.ranked_image) << info.name;
    screen += hooked;
  }
  EXPECT_EQ(screen, 4);
}

TEST(PixelSampler, OtherSamplersGoThroughTheRegistry) {
  EXPECT_FALSE(PixelSampler(settings("halton", 16)).direct());
  PixelSamplerSettings owen = settings("sobol", 16);
  owen.randomize = "owen";  // not the direct path's owen-hash
  EXPECT_FALSE(PixelSampler(owen).direct());
}

TEST(PixelSampler, ACopyDrawsWhatTheOriginalDraws) {
  for (const char* name : {"pmj02", "halton"}) {
    PixelSampler original(settings(name, 16));
    PixelSampler copy(original);
    for (std::uint32_t i = 0; i < 16; ++i) {
      original.start_pixel_sample(5, 1, i);
      copy.start_pixel_sample(5, 1, i);
      EXPECT_EQ(original.get_pixel_2d(), copy.get_pixel_2d()) << name;
      EXPECT_EQ(original.get_1d(), copy.get_1d()) << name;
      std::array<double, 2> a[4], b[4];
      original.get_2d_array(4, a);
      copy.get_2d_array(4, b);
      for (int k = 0; k < 4; ++k) EXPECT_EQ(a[k], b[k]) << name;
    }
  }
}

TEST(PixelSampler, JitteredArraysOfANonSquareCountAreRefusedByName) {
  PixelSampler sampler(settings("jittered", 16));
  sampler.start_pixel_sample(0, 0, 0);
  std::array<double, 2> out[3];
  try {
    sampler.get_2d_array(3, out);
    ADD_FAILURE() << "no error";
  } catch (const invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("n = 3"), std::string::npos) << e.what();
  }
}

TEST(PixelSampler, ContinuedArraysUnderALowMemoryLimitBindPerSample) {
  // A progressive sampler's arrays through its generator are bound once per
  // pixel by a request for all the pixel's (spp · n) array points, which the
  // memory guard checks although they are never allocated: under a limit
  // below them (1024 · 16 · 2 doubles = 256 KiB > 100 kB) the sampler binds
  // per sample instead and draws the same points.
  std::vector<std::array<double, 2>> unlimited, limited;
  for (const bool limit : {false, true}) {
    if (limit) ::setenv("STRATUM_MEMORY_LIMIT", "100000", 1);
    PixelSampler sampler(settings("faure", 1024));
    for (std::uint32_t index : {0u, 1u, 1023u}) {
      sampler.start_pixel_sample(2, 5, index);
      std::array<double, 2> array[16];
      sampler.get_2d_array(16, array);
      (limit ? limited : unlimited).insert((limit ? limited : unlimited).end(), array, array + 16);
    }
    ::unsetenv("STRATUM_MEMORY_LIMIT");
  }
  ASSERT_EQ(limited.size(), 48u);
  EXPECT_EQ(limited, unlimited);
}

/// Sample `index`'s first draw (dimension 0) against the film set: get_1d
/// every third sample (its first coordinate seeded alone), get_2d otherwise
/// (both, the same pixel's state seeded again for the second).
void expect_film_draw(PixelSampler& sampler, const PointSet& film_set, std::uint32_t index, const std::string& name) {
  if (index % 3 == 0) {
    EXPECT_EQ(sampler.get_1d(), film_set(index, 0)) << name << " " << index;
  } else {
    const auto p = sampler.get_2d();
    EXPECT_EQ(p[0], film_set(index, 0)) << name << " " << index;
    EXPECT_EQ(p[1], film_set(index, 1)) << name << " " << index;
  }
}

TEST(PixelSampler, SeededSetsAndArraysEqualTheRegistrys) {
  // faure and halton under owen draw through the registry's SeededGenerator
  // (a seed's keys written in place per pixel and dimension, no generator
  // bound per set): the film set (dimension 0; get_1d seeds its first
  // coordinate only, a later get_2d of the same pixel both) and the
  // continued shadow-ray arrays (dimension 1) equal the registry's sets, in
  // frame 0 and in a later frame, also when a pixel is visited again.
  for (const auto& [name, randomize] : {std::pair{"faure", ""}, std::pair{"halton", "owen"}})
    for (const std::uint32_t frame : {0u, 3u}) {
      PixelSamplerSettings s = settings(name, 16);
      s.randomize = randomize, s.frame = frame;
      PixelSampler sampler(s);
      const std::uint64_t offset = std::uint64_t{frame} * 16;
      for (const auto& [x, y] : {std::pair{3u, 2u}, std::pair{4u, 2u}, std::pair{3u, 2u}}) {
        SamplerRequest film;
        film.n = 16, film.d = 2, film.start = offset, film.randomize = randomize;
        film.seed = PixelSampler::set_seed_for_test(7, x, y, 0);
        const PointSet film_set = generate_points(name, film);
        SamplerRequest arrays;
        arrays.n = 4 * (offset + 16), arrays.d = 2, arrays.randomize = randomize;
        arrays.seed = PixelSampler::array_seed_for_test(7, x, y, 1, PixelSampler::tag_continued);
        const PointSet array_set = generate_points(name, arrays);
        for (std::uint32_t index = 0; index < 16; ++index) {
          sampler.start_pixel_sample(x, y, index);
          expect_film_draw(sampler, film_set, index, name);
          std::array<double, 2> array[4];
          sampler.get_2d_array(4, array);
          for (std::uint32_t i = 0; i < 4; ++i) {
            const std::uint64_t row = 4 * (offset + index) + i;
            EXPECT_EQ(array[i][0], array_set(row, 0)) << name << " " << index << " " << i;
            EXPECT_EQ(array[i][1], array_set(row, 1)) << name << " " << index << " " << i;
          }
        }
      }
    }
}

TEST(PixelSampler, WholeSetPatternsSeededInPlaceEqualTheRegistrys) {
  // n-rooks, multi-jittered and latin-square (made as a whole set, their
  // construction written in place per pixel and dimension), cmj and
  // n-queens (under its default cp: the solution's cells and shifts): the
  // film set (dimension 0: get_1d seeds its first coordinate, a later get_2d
  // of the same pixel both) and each sample's own 4-point shadow-ray array
  // (dimension 1) equal the registry's sets, also when a pixel is visited again.
  for (const char* name : {"n-rooks", "multi-jittered", "latin-square", "cmj", "n-queens"}) {
    PixelSampler sampler(settings(name, 16));
    const unsigned d = std::string(name) == "latin-square" ? 3 : 2;
    for (const auto& [x, y] : {std::pair{3u, 2u}, std::pair{4u, 2u}, std::pair{3u, 2u}}) {
      SamplerRequest film;
      film.n = 16, film.d = d;
      film.seed = PixelSampler::set_seed_for_test(7, x, y, 0);
      const PointSet film_set = generate_points(name, film);
      for (std::uint32_t index = 0; index < 16; ++index) {
        sampler.start_pixel_sample(x, y, index);
        expect_film_draw(sampler, film_set, index, name);
        SamplerRequest arrays;
        arrays.n = 4, arrays.d = d;
        arrays.seed = PixelSampler::array_seed_for_test(7, x, y, 1, index);
        const PointSet array_set = generate_points(name, arrays);
        std::array<double, 2> array[4];
        sampler.get_2d_array(4, array);
        for (std::uint32_t i = 0; i < 4; ++i) {
          EXPECT_EQ(array[i][0], array_set(i, 0)) << name << " " << index << " " << i;
          EXPECT_EQ(array[i][1], array_set(i, 1)) << name << " " << index << " " << i;
        }
      }
    }
  }
}

TEST(PixelSampler, ASpecsParametersReachEverySetTheSamplerDraws) {
  // render -s 'cmj(aspect=2)': the film set (dimension 0) and the 16-point
  // shadow-ray arrays (dimension 1: each sample's own set for a pattern, the
  // pixel's continued set for a progressive sampler) are the registry's sets
  // under the parameters, also where the defaults draw through keyed pairs or
  // pair tables (sobol, zero-two, jittered, halton). Every sampler with
  // parameters is here but the image samplers (below).
  struct Case {
    std::string name;
    std::map<std::string, std::string> params;
    std::uint32_t spp = 16;  ///< also the arrays' count
    /// false where the parameter changes no 2D point: fibonacci's strict
    /// only refuses counts, latin-square's method makes its symbols
    /// (coordinate 2; the renderer draws rows and columns)
    bool moves_points = true;
  };
  const std::vector<Case> specs = {
      {"halton", {{"bases", "5,7"}}},
      {"sobol", {{"order", "natural"}, {"bits", "12"}}},
      {"zero-two", {{"bits", "7"}}},
      {"pmj02bn", {{"candidates", "3"}}},
      {"fibonacci", {{"strict", "1"}}, 13, false},
      {"lattice", {{"generator", "1,5"}}},
      {"kronecker", {{"alpha", "0.3,0.71"}, {"offset", "0.25"}}},
      {"lattice-sequence", {{"generator", "1,7"}}},
      {"grid", {{"strata", "2x8"}}},
      {"jittered", {{"strata", "8x2"}}},
      {"n-rooks", {{"centered", "1"}}},
      {"latin-hypercube", {{"centered", "1"}}},
      {"multi-jittered", {{"strata", "2x8"}}},
      {"cmj", {{"aspect", "2"}}},
      {"n-queens", {{"method", "formula"}}},
      {"latin-square", {{"method", "permuted-cyclic"}}, 16, false},
      {"poisson-disk", {{"periodic", "1"}}},
      {"best-candidate", {{"candidates", "4"}, {"periodic", "0"}}},
  };
  std::set<std::string> covered;
  for (const auto& [name, params, spp, moves_points] : specs) {
    covered.insert(name);
    PixelSamplerSettings s = settings(name, spp);
    s.params = params;
    PixelSampler sampler(s);
    EXPECT_FALSE(sampler.direct()) << name;
    const SamplerInfo& info = find_sampler(name);
    const unsigned d = std::max(2u, info.min_dim);
    const auto registry_set = [&](std::uint64_t n, std::uint64_t seed, bool with_params = true) {
      SamplerRequest request;
      request.n = n, request.d = d, request.seed = seed;
      if (with_params) request.params = params;
      return generate_points(name, request);
    };
    const bool continued = info.flags.progressive;
    bool differs = false;  // from the default parameters' film set somewhere
    for (const auto& [x, y] : {std::pair{3u, 2u}, std::pair{4u, 2u}, std::pair{3u, 2u}}) {
      const PointSet film = registry_set(spp, PixelSampler::set_seed_for_test(7, x, y, 0));
      const PointSet default_film = registry_set(spp, PixelSampler::set_seed_for_test(7, x, y, 0), false);
      const std::uint64_t continued_seed = PixelSampler::array_seed_for_test(7, x, y, 1, PixelSampler::tag_continued);
      const PointSet continued_arrays = continued ? registry_set(spp * spp, continued_seed) : PointSet{};
      for (std::uint32_t index = 0; index < spp; ++index) {
        sampler.start_pixel_sample(x, y, index);
        const auto p = sampler.get_2d();
        EXPECT_EQ(p[0], film(index, 0)) << name << " " << index;
        EXPECT_EQ(p[1], film(index, 1)) << name << " " << index;
        differs = differs || p[0] != default_film(index, 0) || p[1] != default_film(index, 1);
        std::vector<std::array<double, 2>> array(spp);
        sampler.get_2d_array(spp, array.data());
        const PointSet own =
            continued ? PointSet{} : registry_set(spp, PixelSampler::array_seed_for_test(7, x, y, 1, index));
        const PointSet& arrays = continued ? continued_arrays : own;
        const std::uint64_t first = continued ? std::uint64_t{spp} * index : 0;
        for (std::uint32_t i = 0; i < spp; ++i) {
          EXPECT_EQ(array[i][0], arrays(first + i, 0)) << name << " " << index << " " << i;
          EXPECT_EQ(array[i][1], arrays(first + i, 1)) << name << " " << index << " " << i;
        }
      }
    }
    EXPECT_EQ(differs, moves_points) << name << ": the parameters moved none of the film points, or some";
  }
  for (const SamplerInfo& info : samplers()) {
    const bool image = info.zsobol_image || info.ranked_image;
    if (!info.params.empty() && !image && !info.flags.space_time) {
      EXPECT_TRUE(covered.contains(info.name)) << info.name << " has parameters and no case here";
    }
  }
  // Bad values are the registry's errors, named.
  PixelSamplerSettings bad = settings("cmj", 16);
  bad.params = {{"aspect", "-1"}};
  EXPECT_THROW(PixelSampler{bad}, invalid_argument);
  bad = settings("fibonacci", 16);
  bad.params = {{"strict", "1"}};
  EXPECT_THROW(PixelSampler{bad}, invalid_argument);
  bad = settings("jittered", 16);
  bad.params = {{"strata", "4x8"}};
  try {
    PixelSampler{bad};
    ADD_FAILURE() << "jittered(strata=4x8) at 16 spp accepted";
  } catch (const invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("strata"), std::string::npos) << e.what();
  }
}

TEST(PixelSampler, AnImageSamplerTakesItsTileButNotItsPixel) {
  // sobol-bn(table=FILE) draws over that rank tile (here the committed tile
  // mirrored in x): the registry's pixel samples of that tile, not the
  // committed tile's. pixel and resolution are the renderer's and refused.
  const BlueNoiseTable& committed = default_blue_noise_table(BlueNoiseBase::sobol);
  BlueNoiseTable mirrored = committed;
  for (std::uint32_t y = 0; y < committed.size; ++y)
    for (std::uint32_t x = 0; x < committed.size; ++x)
      for (std::uint32_t p = 0; p < committed.pairs(); ++p)
        mirrored.ranks[(std::size_t{y} * committed.size + x) * committed.pairs() + p] =
            committed.rank(committed.size - 1 - x, y, p);
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("stratum-pixel-sampler-tile-" + std::to_string(::getpid()) + ".bin");
  std::ofstream(path, std::ios::binary) << serialize_blue_noise_table(mirrored);
  PixelSamplerSettings s = settings("sobol-bn", 4);
  s.params = {{"table", path.string()}};
  PixelSampler tiled(s);
  PixelSampler plain(settings("sobol-bn", 4));
  bool differs = false;
  for (const auto& [x, y] : {std::pair{0u, 0u}, std::pair{1u, 0u}, std::pair{5u, 9u}}) {
    SamplerRequest request;
    request.n = 4, request.d = 2, request.seed = 7;
    request.params = {{"table", path.string()}, {"pixel", std::to_string(x) + "," + std::to_string(y)}};
    const PointSet set = generate_points("sobol-bn", request);
    for (std::uint32_t index = 0; index < 4; ++index) {
      tiled.start_pixel_sample(x, y, index);
      plain.start_pixel_sample(x, y, index);
      const auto p = tiled.get_2d();
      const auto q = plain.get_2d();
      EXPECT_EQ(p[0], set(index, 0)) << x << "," << y << " " << index;
      EXPECT_EQ(p[1], set(index, 1)) << x << "," << y << " " << index;
      differs = differs || p != q;
    }
  }
  EXPECT_TRUE(differs);
  std::filesystem::remove(path);
  for (const auto& [name, key, value] :
       {std::tuple{"zsobol", "resolution", "64"}, std::tuple{"sobol-bn", "pixel", "1,2"},
        std::tuple{"zsobol", "pixel", "0,0"}}) {
    PixelSamplerSettings refused = settings(name, 4);
    refused.params = {{key, value}};
    try {
      PixelSampler{refused};
      ADD_FAILURE() << name << " took " << key;
    } catch (const invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(std::string(key) + " is the renderer's own"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace stratum::render
