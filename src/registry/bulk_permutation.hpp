#pragma once
/// random_permutation (stratum/patterns/strata.hpp) for bulk generation: the
/// same permutation of {0, …, n−1} for the same key, with the swap targets of
/// 2048 steps at a time drawn first in one loop that vectorizes (each step's
/// draw depends only on (key, step)), then the swaps.
#include <cstdint>

namespace stratum::registry_support {

void bulk_random_permutation(std::uint32_t* values, std::uint64_t n, std::uint64_t key);

}  // namespace stratum::registry_support
