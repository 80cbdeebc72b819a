/// The edge family of the measure registry: exact edge discrepancy and
/// Mitchell's random-edge discrepancy (algorithms in edge_discrepancy*.cpp).
#include <charconv>
#include <cstdint>
#include <string>

#include "measure_families.hpp"
#include "stratum/analysis/edge_discrepancy.hpp"
#include "stratum/util/error.hpp"

namespace stratum::analysis::measure_families {

namespace {

constexpr std::uint64_t max_lines = std::uint64_t{1} << 32;

}  // namespace

std::vector<MeasureInfo> edge() {
  std::vector<MeasureInfo> list;
  list.push_back({
      .name = "edge",
      .description = "exact edge (half-plane) discrepancy: sup over lines of |fraction of points on one side - area|, "
                     "points on the line counted both ways (Dobkin, Eppstein, Mitchell 1996); O(N^2 log N)",
      .min_dim = 2,
      .max_dim = 2,
      .params = {},
      .validate = nullptr,
      .compute =
          [](const PointView& points, const MeasureRequest& request) {
            const EdgeDiscrepancy exact = edge_discrepancy(points, request.threads);
            MeasureResult result;
            result.value = exact.value;
            result.kind = "exact";
            result.extras = {{"line_angle", exact.line.angle}, {"line_offset", exact.line.offset}};
            return result;
          },
      // The best line through each point, and each worker's rays and
      // collinear groups about its centre (32 bytes each, at most N).
      .working_bytes =
          [](std::size_t n, std::size_t, const MeasureRequest& request) {
            return (24 + 64 * concurrent_workers(request.threads)) * double(n);
          },
  });
  list.push_back({
      .name = "edge-random",
      .description = "Mitchell's random-edge discrepancy (Mitchell 1992): RMS of |fraction - area| over random lines "
                     "from the motion-invariant measure; extras mean and max",
      .min_dim = 2,
      .max_dim = 2,
      .params = {params::integer("lines", "number of random lines L", "10000", closed(1, double(max_lines))),
                 params::integer("seed", "seed of the random lines", "0", half_open(0, 0x1p64))},
      .validate = nullptr,
      .compute =
          [](const PointView& points, const MeasureRequest& request) {
            const auto estimate = random_edge_discrepancy(points, request.values.unsigned_integer("lines"),
                                                          request.values.unsigned_integer("seed"), request.threads);
            MeasureResult result;
            result.value = estimate.rms;
            result.kind = "estimate";
            result.extras = {
                {"mean", estimate.mean}, {"max", estimate.max}, {"lines", static_cast<double>(estimate.lines)}};
            return result;
          },
      // One value per line, kept to sum in index order (the same result
      // for any thread count): 2^32 lines are 32 GiB.
      .working_bytes =
          [](std::size_t, std::size_t, const MeasureRequest& request) {
            return 8 * double(request.values.unsigned_integer("lines"));
          },
  });
  return list;
}

}  // namespace stratum::analysis::measure_families
