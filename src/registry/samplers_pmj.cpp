/// Registry entries: progressive multi-jittered (0,2) points (pmj02).
#include "families.hpp"
#include "stratum/sequences/pmj.hpp"
#include "support.hpp"

namespace stratum::registry_families {

using namespace registry_support;

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
      .properties = {"index-addressable", "progressive", "(0,2)-sequence", "multi-jittered"},
      .randomizers = {"none"},  // its own seeded randomness: a new seed is a new Owen-scrambled realization
      .counts = "any n >= 1 (every power-of-two prefix is a (0,k,2)-net)",
      .params = {},
      .validate = nullptr,
      .count = requested_count,
      .generate =
          [](const SamplerRequest& request) {
            const Pmj02 pmj(request.d, request.seed);
            return fill_index_addressable(*request.n, request.d, request.threads, [&](std::uint64_t i, unsigned j) {
              return pmj.sample(request.start + i, j);
            });
          },
  });

  return list;
}

}  // namespace stratum::registry_families
