/// Fisher–Yates (Durstenfeld 1964) with Lemire's draws (uniform_below in
/// stratum/util/hash.hpp), its hashes unrolled: step i draws
/// w = hash64(hash64(key, i), 0) and takes the high word of w · i, unless the
/// low word is below i, where uniform_below may reject and is called itself.
/// For i ≤ 2^32 the 64 × 64-bit product is two 32 × 64-bit ones, which vector
/// units have.
#include "bulk_permutation.hpp"

#include <algorithm>

#include "stratum/patterns/strata.hpp"
#include "stratum/util/hash.hpp"

namespace stratum::registry_support {
namespace {

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define STRATUM_PERMUTATION_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define STRATUM_PERMUTATION_CLONES
#endif

constexpr std::uint64_t golden = 0x9e3779b97f4a7c15ULL;  // hash64's constants
constexpr std::uint64_t counter_multiplier = 0xd1342543de82ef95ULL;
constexpr std::uint64_t counter_addend = 0x632be59bd9b4e019ULL;
constexpr std::uint64_t rejected = ~std::uint64_t{0};

/// out[t] = the swap target of step i = top − t (t < count, i ≥ 2), or
/// `rejected` where the fast path cannot decide. mixed_key = mix64(key + golden).
STRATUM_PERMUTATION_CLONES
void swap_targets(std::uint64_t mixed_key, std::uint64_t top, std::uint64_t count, std::uint64_t* __restrict out) {
  for (std::uint64_t t = 0; t < count; ++t) {
    const std::uint64_t i = top - t;
    const std::uint64_t step_key = mix64((mixed_key ^ (i * counter_multiplier + counter_addend)) + golden);
    const std::uint64_t word = mix64((mix64(step_key + golden) ^ counter_addend) + golden);  // hash64(step_key, 0)
    const std::uint64_t low_product = (word & 0xffffffffULL) * i, high_product = (word >> 32) * i;
    const std::uint64_t high = (high_product + (low_product >> 32)) >> 32;
    out[t] = word * i < i ? rejected : high;
  }
}

}  // namespace

void bulk_random_permutation(std::uint32_t* values, std::uint64_t n, std::uint64_t key) {
  constexpr std::uint64_t chunk = 2048;
  std::uint64_t targets[chunk];
  for (std::uint64_t i = 0; i < n; ++i) values[i] = static_cast<std::uint32_t>(i);
  const std::uint64_t mixed_key = mix64(key + golden);
  for (std::uint64_t top = n; top > 1;) {
    const std::uint64_t count = std::min(chunk, top - 1);
    swap_targets(mixed_key, top, count, targets);
    for (std::uint64_t t = 0; t < count; ++t) {
      const std::uint64_t i = top - t;
      const std::uint64_t j = targets[t] != rejected ? targets[t] : uniform_below(i, key, i);
      std::swap(values[i - 1], values[j]);
    }
    top -= count;
  }
}

}  // namespace stratum::registry_support
