#include "stratum/analysis/integrate_tolerance.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"

namespace stratum::analysis {

namespace {

/// Every n of the doubling, checked against the sampler before any work (a
/// pattern that takes only square n, say, is refused at once, not after the
/// first steps).
void check_every_step(const ToleranceRequest& request, unsigned d) {
  const SamplerChoice& choice = request.integration.sampler;
  const SamplerInfo& info = find_sampler(choice.name);
  for (std::uint64_t n = request.integration.n; n <= request.max_n; n *= 2) {
    SamplerRequest sampler;
    sampler.n = n;
    sampler.d = d;
    sampler.randomize = choice.randomize;
    sampler.params = choice.params;
    try {
      validate_request(info, sampler);
    } catch (const invalid_argument& refused) {
      if (n == request.integration.n) throw;
      throw invalid_argument("max-n", std::to_string(request.max_n),
                             "doubling from n = " + std::to_string(request.integration.n) +
                                 " reaches n = " + std::to_string(n) + ", which " + choice.name + " refuses (" +
                                 refused.what() + "); give a smaller --max-n or a sampler that takes every 2^k n");
    }
    if (n > request.max_n / 2) break;
  }
}

}  // namespace

ToleranceResult integrate_to_tolerance(const ToleranceRequest& request) {
  require(std::isfinite(request.abs_tol) && request.abs_tol >= 0, "abs-tol", request.abs_tol,
          "must be a finite real >= 0");
  require(std::isfinite(request.rel_tol) && request.rel_tol >= 0 && request.rel_tol < 1, "rel-tol", request.rel_tol,
          "must be a real in [0, 1)");
  if (request.abs_tol == 0 && request.rel_tol == 0)
    throw invalid_argument("abs-tol", "0", "give --abs-tol or --rel-tol greater than 0");
  const IntegrationRequest& first = request.integration;
  require(first.n >= 1, "n", first.n, "must be a positive integer");
  require(request.max_n >= first.n, "max-n", request.max_n, "must be at least n = " + std::to_string(first.n));
  const auto integrand = make_integrand(first.integrand.name, first.integrand.d, first.integrand.params);
  check_every_step(request, static_cast<unsigned>(integrand->dimension()));

  ToleranceResult out;
  IntegrationRequest step = first;
  while (true) {
    out.result = integrate(step);
    const IntegrationResult& r = out.result;
    if (!std::isfinite(r.half_width))
      throw invalid_argument("sampler", r.sampler + ":" + r.randomize,
                             "gives no error estimate (" + r.standard_error_kind +
                                 "), so no tolerance can be met: choose a randomized sampler or more runs");
    out.target = std::max(request.abs_tol, request.rel_tol * std::fabs(r.estimate));
    out.steps.push_back({step.n, r.estimate, r.half_width, out.target, r.seconds});
    out.met = r.half_width <= out.target;
    if (out.met || step.n > request.max_n / 2) return out;
    step.n *= 2;
  }
}

ToleranceResult integrate_with(const IntegrationRequest& request, const ToleranceOptions& tolerance) {
  if (!tolerance.any()) {
    if (tolerance.max_n)
      throw invalid_argument("max-n", std::to_string(*tolerance.max_n),
                             "applies only with a tolerance, abs-tol or rel-tol");
    ToleranceResult out;
    out.result = integrate(request);
    return out;
  }
  ToleranceRequest to_tolerance{request, tolerance.abs_tol.value_or(0), tolerance.rel_tol.value_or(0)};
  if (tolerance.max_n) to_tolerance.max_n = *tolerance.max_n;
  return integrate_to_tolerance(to_tolerance);
}

}  // namespace stratum::analysis
