#pragma once
/// The measure registry's families, one source file each.
#include <cstddef>
#include <vector>

#include "stratum/analysis/measures.hpp"
#include "stratum/registry/spec.hpp"

namespace stratum::analysis::measure_families {
/// Workers a measure's parallel loop runs at once (threads 0: every core,
/// as resolve_threads counts them): the count of per-worker scratch
/// buffers its working_bytes allows for.
inline double concurrent_workers(unsigned threads) {
  return threads != 0 ? double(threads) : double(resolve_threads(0));
}

std::vector<MeasureInfo> l2();        // measures_l2.cpp: l2-star, cd, wd, md
std::vector<MeasureInfo> star();      // measures_star.cpp: star (exact and bounds)
std::vector<MeasureInfo> edge();      // measures_edge.cpp: edge, edge-random
std::vector<MeasureInfo> geometry();  // measures_geometry.cpp: t-value, latin, min-distance, poisson-radius
std::vector<MeasureInfo> local();     // measures_local.cpp: star-box, koksma-hlawka (2D)
}  // namespace stratum::analysis::measure_families
