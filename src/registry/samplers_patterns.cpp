/// Registry entries of the finite patterns.
#include "families.hpp"
#include "stratum/patterns/random.hpp"
#include "support.hpp"

namespace stratum::registry_families {

using namespace registry_support;

static std::optional<std::uint64_t> requested_count(const SamplerRequest& request) { return request.n; }

std::vector<SamplerInfo> patterns() {
  std::vector<SamplerInfo> list;

  list.push_back({
      .name = "random",
      .kind = "pattern",
      .description = "independent uniform points from a counter-based generator",
      .min_dim = 1,
      .max_dim = 1u << 16,
      .properties = {"index-addressable", "unstratified"},
      .randomizers = {"none"},
      .counts = "any n >= 1",
      .params = {},
      .validate = nullptr,
      .count = requested_count,
      .generate =
          [](const SamplerRequest& request) {
            const RandomPattern random(request.seed);
            return fill_index_addressable(*request.n, request.d, request.threads,
                                          [&](std::uint64_t i, unsigned j) { return random.sample(i, j); });
          },
  });

  return list;
}

}  // namespace stratum::registry_families
