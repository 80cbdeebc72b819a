/// Registry entries of the index-addressable sequences.
#include "families.hpp"
#include "stratum/sequences/halton.hpp"
#include "support.hpp"

namespace stratum::registry_families {

using namespace registry_support;

static std::optional<std::uint64_t> requested_count(const SamplerRequest& request) { return request.n; }

std::vector<SamplerInfo> sequences() {
  std::vector<SamplerInfo> list;

  list.push_back({
      .name = "halton",
      .kind = "sequence",
      .description = "Halton points: radical inverse in the d-th prime base (Halton 1960)",
      .min_dim = 1,
      .max_dim = Halton::max_dimensions,
      .properties = {"index-addressable", "progressive", "low-discrepancy"},
      .randomizers = {"none"},
      .counts = "any n >= 1",
      .params = {},
      .validate = nullptr,
      .count = requested_count,
      .generate =
          [](const SamplerRequest& request) {
            const Halton halton(request.d);
            return fill_index_addressable(*request.n, request.d, request.threads, [&](std::uint64_t i, unsigned j) {
              return halton.sample(request.start + i, j);
            });
          },
  });

  list.push_back({
      .name = "hammersley",
      .kind = "pattern",
      .description = "Hammersley points (i/N, phi_2(i), phi_3(i), ...) (Hammersley 1964)",
      .min_dim = 1,
      .max_dim = Hammersley::max_dimensions,
      .properties = {"low-discrepancy", "Latin in dimension 0"},
      .randomizers = {"none"},
      .counts = "any n >= 1",
      .params = {},
      .validate = nullptr,
      .count = requested_count,
      .generate =
          [](const SamplerRequest& request) {
            const Hammersley hammersley(*request.n, request.d);
            return fill_index_addressable(*request.n, request.d, request.threads,
                                          [&](std::uint64_t i, unsigned j) { return hammersley.sample(i, j); });
          },
  });

  return list;
}

}  // namespace stratum::registry_families
