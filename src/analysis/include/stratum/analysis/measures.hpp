#pragma once
/// The registry of point-set measures: discrepancies (star, L2-star, CD, WD,
/// MD, edge, random-edge), stratification (t-value, Latin property) and
/// geometry (minimum distance, Poisson radius). `stratum discrepancy`,
/// `stratum.discrepancy` and the tests iterate over this list. Each family
/// lives in src/analysis/measures_*.cpp; the algorithms in their own files.
#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "stratum/registry/params.hpp"
#include "stratum/util/point_set.hpp"

namespace stratum::analysis {

using stratum::PointView;  ///< n points of d coordinates, borrowed (stratum/util/point_set.hpp)

struct MeasureRequest {
  std::map<std::string, std::string> params;  ///< measure-specific, as text ("lines=10000")
  unsigned threads = 1;
  /// `params` bound to the measure's schema by compute_measure; entries read here.
  ParamValues values{};
};

struct MeasureResult {
  double value = 0;  ///< the measure (for bounds: the upper bound)
  /// "exact", "bounds" (value lies in [lower, upper]) or "estimate" (random, e.g. random-edge RMS)
  std::string kind = "exact";
  std::optional<double> lower;
  std::optional<double> upper;
  std::map<std::string, double> extras;  ///< e.g. {"mean": ..., "max": ...} for random-edge
};

struct MeasureInfo {
  std::string name;         ///< "star", "l2-star", "cd", "wd", "md", "edge", "edge-random", "t-value", ...
  std::string description;  ///< one line, with the definition's source
  std::size_t min_dim = 1;
  std::size_t max_dim = 0;    ///< 0: no limit
  std::vector<Param> params;  ///< the schema of MeasureRequest::params
  /// Checks params and dimension-specific limits (e.g. an exact method's
  /// largest d), throwing stratum::invalid_argument that says which method can.
  std::function<void(const PointView&, const MeasureRequest&)> validate;
  std::function<MeasureResult(const PointView&, const MeasureRequest&)> compute;
  /// Bytes compute allocates besides the points, for n × d points (the
  /// memory guard, stratum/memory.hpp: a command that generates the points
  /// checks both before it starts); empty where it is small.
  std::function<double(std::size_t n, std::size_t d, const MeasureRequest&)> working_bytes;
};

/// Every measure, in a stable order.
const std::vector<MeasureInfo>& measures();

/// The measure called `name`; throws invalid_argument listing the valid names.
const MeasureInfo& find_measure(std::string_view name);

/// Checks the points (n ≥ 2, every coordinate finite and in [0,1]: the
/// message names the row and column), the dimension and the params, then
/// computes. The one entry point the faces call.
MeasureResult compute_measure(std::string_view name, const PointView& points, const MeasureRequest& request);

/// Refuses (stratum::memory_error) unless the n × d points and what the
/// measure `name` allocates for them fit in memory: before they are generated.
void require_measure_memory(std::string_view name, std::size_t n, std::size_t d, const MeasureRequest& request);

/// Throws invalid_argument naming row and column of the first coordinate
/// that is not finite or not in [0,1], or if n < 2 or d < 1.
void check_unit_cube(const PointView& points);

}  // namespace stratum::analysis
