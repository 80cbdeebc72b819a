/// Registry entries: progressive multi-jittered (0,2) points (pmj02) and
/// their blue-noise variant (pmj02bn).
#include <algorithm>
#include <string>

#include "families.hpp"
#include "stratum/memory.hpp"
#include "stratum/patterns/keyed_pairs.hpp"
#include "stratum/sequences/pmj.hpp"
#include "stratum/sequences/pmj02bn.hpp"
#include "support.hpp"

namespace stratum::registry_families {

using namespace registry_support;

static Pmj02 pmj02_of(const SamplerRequest& request) { return Pmj02(request.d, request.seed); }

std::vector<SamplerInfo> pmj() {
  std::vector<SamplerInfo> list;

  list.push_back({
      .name = "pmj02",
      .kind = "sequence",
      .description =
          "progressive multi-jittered (0,2) sequence (Christensen, Kensler, Kilpatrick 2018), generated "
          "statelessly from (seed, index) as in Helmer, Christensen, Kensler 2021; distributed exactly as an "
          "Owen-scrambled digital (0,2)-sequence, so every 2^k prefix is a (0,k,2)-net. Dimensions "
          "(2t, 2t+1) are further independent pmj02 pairs, index-shuffled within each power-of-two block",
      .min_dim = 1,
      .max_dim = Pmj02::max_dimensions,
      .flags = {.index_addressable = true, .progressive = true, .self_randomized = true, .zero_two_net = true},
      .properties = {"(0,2)-sequence", "multi-jittered"},
      // its own seeded randomness: a new seed is a new Owen-scrambled realization
      .randomization = {RandomizerFamily::seeded, Randomizer::none},
      .counts = "any n >= 1 (every power-of-two prefix is a (0,k,2)-net)",
      .params = {},
      .validate = nullptr,
      .count = requested_count,
      .generate = generate_rotated(pmj02_of),
      .bind = bind_rotated(pmj02_of),
      .keyed_pairs = keyed_under<Pmj02Pairs>(Randomizer::none),
  });

  list.push_back({
      .name = "pmj02bn",
      .kind = "sequence",
      .description =
          "progressive multi-jittered (0,2) sequence with blue-noise properties (Christensen, Kensler, Kilpatrick "
          "2018): each point in the square stratum of the (0,2) construction, the best of k candidates there "
          "(farthest, toroidally, from the points before it); every 2^k prefix a (0,k,2)-net whose points are "
          "also spread apart (blue noise within the set, unlike sobol-bn/pmj02-bn's blue noise across pixels)",
      .min_dim = 1,
      .max_dim = 2,
      .flags = {.progressive = true, .self_randomized = true, .zero_two_net = true},
      .properties = {"(0,2)-sequence", "multi-jittered", "blue noise (within the point set)"},
      .randomization = {RandomizerFamily::seeded, Randomizer::none},  // its own seeded randomness
      .counts = "any n >= 1 with start + n <= 2^31 (points are placed one after another: start + n are made)",
      .params = {params::integer("candidates",
                                 "candidates per point, the farthest from the points before it kept (1: plain "
                                 "stochastic pmj02 digits)",
                                 std::to_string(Pmj02Bn::default_candidates), closed(1, Pmj02Bn::max_candidates))},
      .validate =
          [](const SamplerRequest& request) {
            const std::uint64_t total = request.start + *request.n;
            require(total <= Pmj02Bn::max_points, "n", std::to_string(*request.n),
                    "pmj02bn places start + n points one after another; start + n must be at most 2^31");
            // The sequence's bits, coordinates and neighbour grid: about 44 bytes a point.
            require_memory(44.0 * static_cast<double>(total), std::to_string(total) + " pmj02bn points being placed");
          },
      .count = requested_count,
      .generate =
          [](const SamplerRequest& request) {
            const Pmj02Bn sequence(request.seed, static_cast<unsigned>(request.values.integer("candidates")));
            const std::vector<std::uint64_t> bits = sequence.generate_bits(request.start + *request.n);
            PointSet points = allocate_points(*request.n, request.d);
            for (std::uint64_t i = 0; i < *request.n; ++i)
              for (unsigned j = 0; j < request.d; ++j)
                points.data[i * request.d + j] = bits_to_double(bits[2 * (request.start + i) + j]);
            return points;
          },
  });

  return list;
}

}  // namespace stratum::registry_families
