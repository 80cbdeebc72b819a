/// Registry entries of the space-time patterns (LECTURE.md section 8): n = m²
/// points (x, y, t), one per stratum of an m×m grid, each in its time slot.
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>

#include "families.hpp"
#include "stratum/spacetime/cook_pattern.hpp"
#include "stratum/spacetime/magic_square.hpp"
#include "stratum/spacetime/time_assignment.hpp"
#include "stratum/util/error.hpp"
#include "support.hpp"

namespace stratum::registry_families {

using namespace registry_support;

namespace {

// m with m² = n, or 0 when n is not a perfect square (or too large).
std::uint32_t square_root(std::uint64_t n) {
  auto m = static_cast<std::uint64_t>(std::sqrt(static_cast<double>(n)));
  while (m * m > n) --m;
  while ((m + 1) * (m + 1) <= n) ++m;
  return m * m == n && m <= SlotTable::max_order ? static_cast<std::uint32_t>(m) : 0;
}

void require_square(const SamplerRequest& request, const std::string& name) {
  require(square_root(*request.n) != 0, "n", *request.n,
          name + " takes n = m^2 points, one per stratum of an m x m grid, m <= 65535 (n = 1, 4, 9, 16, 25, ...)");
}

SamplerInfo spacetime_entry(std::string name, std::string description, std::vector<std::string> properties,
                            std::string counts, std::function<void(const SamplerRequest&)> validate,
                            std::function<SlotTable(std::uint32_t, std::uint64_t)> table) {
  return {
      .name = std::move(name),
      .kind = "pattern",
      .description = std::move(description),
      .min_dim = 3,
      .max_dim = 3,
      .flags = {.self_randomized = true, .space_time = true},
      .properties = std::move(properties),
      .randomization = {RandomizerFamily::seeded, Randomizer::none},
      .counts = std::move(counts),
      .params = {},
      .validate = std::move(validate),
      .count = requested_count,
      .generate =
          [table](const SamplerRequest& request) {
            const SpaceTimePattern pattern(table(square_root(*request.n), request.seed), request.seed);
            return fill_index_addressable(*request.n, 3, request.threads,
                                          [&](std::uint64_t i, unsigned j) { return pattern.sample(i, j); });
          },
  };
}

}  // namespace

std::vector<SamplerInfo> spacetime() {
  std::vector<SamplerInfo> list;
  const std::string layout =
      " (x, y) jittered in stratum (row, column), t jittered in the stratum's slot "
      "[k/m^2, (k+1)/m^2); row r is y in [r/m, (r+1)/m)";

  list.push_back(spacetime_entry(
      "spacetime-random", "space-time pattern, time slots a seeded random permutation of the m^2 strata" + layout,
      {"stratified in (x, y)", "stratified in t (one point per slot)"}, "n = m^2 (1, 4, 9, 16, ...)",
      [](const SamplerRequest& request) { require_square(request, "spacetime-random"); },
      [](std::uint32_t m, std::uint64_t seed) { return random_slots(m, seed); }));

  list.push_back(spacetime_entry(
      "spacetime-cook",
      "space-time pattern with Cook's slot table (the lecture's 4x4 for m = 4; for other m a fixed random table "
      "whose edge-adjacent strata differ by >= m slots)" +
          layout,
      {"stratified in (x, y)", "stratified in t", "edge neighbours far apart in time"}, "n = m^2 (1, 4, 9, 16, ...)",
      [](const SamplerRequest& request) { require_square(request, "spacetime-cook"); },
      [](std::uint32_t m, std::uint64_t) { return cook_slots(m); }));

  list.push_back(spacetime_entry(
      "spacetime-magic",
      "space-time pattern with a pan-diagonal magic square as slot table (the lecture's for m = 4)" + layout,
      {"stratified in (x, y)", "stratified in t", "equal mean time on every row, column and broken diagonal"},
      "n = m^2 with m = 1 or m >= 4, m mod 4 != 2 (1, 16, 25, 49, 64, 81, 121, 144, ...)",
      [](const SamplerRequest& request) {
        const std::uint32_t m = square_root(*request.n);
        require(m != 0 && pandiagonal_magic_exists(m), "n", *request.n,
                "spacetime-magic takes n = m^2 where a pan-diagonal magic square of order m exists: m = 1 or "
                "m >= 4 with m mod 4 != 2 (n = 1, 16, 25, 49, 64, 81, 121, 144, 169, ...), m <= 65535");
      },
      [](std::uint32_t m, std::uint64_t) { return pandiagonal_magic_square(m); }));

  return list;
}

}  // namespace stratum::registry_families
