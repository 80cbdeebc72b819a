/// Registry entries: Poisson-disk and best-candidate patterns.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "families.hpp"
#include "stratum/patterns/best_candidate.hpp"
#include "stratum/patterns/poisson_disk.hpp"
#include "stratum/util/error.hpp"
#include "support.hpp"

namespace stratum::registry_families {

using namespace registry_support;

namespace {

unsigned candidates_param(const SamplerRequest& request) {
  return static_cast<unsigned>(request.values.integer("candidates"));
}

PointSet to_point_set(const std::vector<double>& coordinates, unsigned d) {
  PointSet points = allocate_points(coordinates.size() / d, d);
  std::copy(coordinates.begin(), coordinates.end(), points.data.get());
  return points;
}

// Memory a maximal set at radius r takes while it is made, against the
// registry's limit (half the physical memory).
void require_fits(const SamplerRequest& request, double radius, bool periodic, const std::string& what) {
  const double bytes = PoissonDisk::working_bytes(request.d, radius, periodic);
  const double limit = static_cast<double>(max_coordinates()) * sizeof(double);
  const double estimate = PoissonDisk::estimated_count(request.d, radius, periodic);
  require(bytes <= limit && estimate < 0x1.0p31, what,
          what == "radius" ? to_message_string(radius) : std::to_string(*request.n),
          "a maximal Poisson-disk set in d = " + std::to_string(request.d) + " at radius " + to_message_string(radius) +
              " has about " + to_message_string(std::round(estimate)) + " points and needs about " +
              to_message_string(std::round(bytes / 0x1.0p20)) + " MiB; the limit is " +
              to_message_string(std::round(limit / 0x1.0p20)) + " MiB and 2^31 points");
}

void validate_poisson(const SamplerRequest& request) {
  const bool periodic = request.values.flag("periodic");
  if (request.radius) {
    require_fits(request, *request.radius, periodic, "radius");
    if (request.n) {
      const double bound = PoissonDisk::packing_bound(request.d, *request.radius, periodic);
      require(static_cast<double>(*request.n) <= bound, "n", *request.n,
              "no " + std::to_string(*request.n) + " points in d = " + std::to_string(request.d) +
                  " can be at distance >= " + to_message_string(*request.radius) +
                  " from each other (packing bound about " + to_message_string(std::floor(bound)) +
                  "); ask for fewer points or a smaller radius");
    }
  } else {
    const double radius = PoissonDisk::radius_for_count(static_cast<double>(*request.n) * 1.2, request.d, periodic);
    require_fits(request, radius, periodic, "n");
  }
}

PointSet generate_poisson(const SamplerRequest& request) {
  const unsigned candidates = candidates_param(request);
  const bool periodic = request.values.flag("periodic");
  if (!request.radius)
    return to_point_set(PoissonDisk::with_count(*request.n, request.d, request.seed, candidates, periodic), request.d);
  const PoissonDisk disk(request.d, *request.radius, request.seed, candidates, periodic);
  return to_point_set(request.n ? disk.subset(*request.n) : disk.maximal_set(), request.d);
}

// Mitchell's cost grows as k·n²/2 candidates; a candidate costs about
// 3-5 ns in 1D and 2D, 25 ns in 3D and 180 ns in 4D (measured), so these
// budgets keep a request to about a second.
int best_candidate_budget_log2(unsigned d) { return d <= 2 ? 27 : d == 3 ? 25 : 23; }

void validate_best_candidate(const SamplerRequest& request) {
  const unsigned k = candidates_param(request);
  const std::uint64_t total = BestCandidate::candidate_count(*request.n, k);
  const int log2 = best_candidate_budget_log2(request.d);
  const std::uint64_t budget = std::uint64_t{1} << log2;
  if (total <= budget) return;
  // Largest n within the budget for this k.
  auto largest = static_cast<std::uint64_t>(std::floor(0.5 + std::sqrt(0.25 + 2.0 * static_cast<double>(budget) / k)));
  while (BestCandidate::candidate_count(largest, k) > budget) --largest;
  throw invalid_argument("n", std::to_string(*request.n),
                         "best-candidate evaluates candidates*n*(n-1)/2 = " + std::to_string(total) +
                             " candidates (Mitchell's quadratic cost), more than the limit of 2^" +
                             std::to_string(log2) + " in d = " + std::to_string(request.d) +
                             "; with candidates=" + std::to_string(k) + " n must be at most " +
                             std::to_string(largest) + " (a smaller candidates= allows more)");
}

}  // namespace

std::vector<SamplerInfo> poisson() {
  std::vector<SamplerInfo> list;

  list.push_back({
      .name = "poisson-disk",
      .kind = "pattern",
      .description =
          "maximal Poisson-disk set: Bridson 2007 dart throwing, completed to maximal after Ebeida et al. 2012",
      .min_dim = 1,
      .max_dim = PoissonDisk::max_dimensions,
      .flags = {.self_randomized = true},
      .properties = {"blue noise", "minimum distance >= radius", "maximal (radius alone)"},
      .randomization = {RandomizerFamily::seeded, Randomizer::none},
      .counts = "radius alone: the maximal set (its size follows from the radius); n alone: exactly n points "
                "(radius chosen from n); n and radius: exactly n points at distance >= radius, if the maximal set "
                "has that many",
      .n_optional = true,
      .params = {params::integer("candidates", "Bridson's k: candidates tried around an active point before it retires",
                                 std::to_string(PoissonDisk::default_candidates),
                                 closed(1, PoissonDisk::max_candidates)),
                 params::flag("periodic", "1: toroidal distances (the pattern tiles space)", "0")},
      .validate = validate_poisson,
      .count = requested_count,
      .generate = generate_poisson,
  });

  list.push_back({
      .name = "best-candidate",
      .kind = "pattern",
      .description = "Mitchell's best-candidate pattern: point i is the best of k*i uniform candidates (Mitchell 1991)",
      .min_dim = 1,
      .max_dim = BestCandidate::max_dimensions,
      .flags = {.self_randomized = true},
      .properties = {"blue noise", "progressive (every prefix is a best-candidate set)"},
      .randomization = {RandomizerFamily::seeded, Randomizer::none},
      .counts = "any n >= 1 with candidates*n*(n-1)/2 <= 2^27 (d <= 2), 2^25 (d = 3), 2^23 (d = 4): "
                "n <= 5181, 2591, 1295 for candidates=10",
      .params = {params::integer("candidates", "Mitchell's multiplier k: point i is the best of k*i candidates",
                                 std::to_string(BestCandidate::default_candidates),
                                 closed(1, BestCandidate::max_candidates)),
                 params::flag("periodic",
                              "1: toroidal distances, as Mitchell (the pattern tiles the plane); 0: "
                              "Euclidean",
                              "1")},
      .validate = validate_best_candidate,
      .count = requested_count,
      .generate =
          [](const SamplerRequest& request) {
            const unsigned k = candidates_param(request);
            const BestCandidate pattern(request.d, request.seed, k, request.values.flag("periodic"));
            PointSet points = allocate_points(*request.n, request.d);
            pattern.generate(*request.n, points.data.get());
            return points;
          },
  });

  return list;
}

}  // namespace stratum::registry_families
