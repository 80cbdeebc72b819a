// Views that a kernel receives (docs/gpu.md) give the generator's own
// numbers, also when they read relocated copies of its arrays (as a kernel
// reads device copies); the bit helpers equal std::'s.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include "stratum/randomizers/digit_permutation.hpp"
#include "stratum/randomizers/owen_base_b.hpp"
#include "stratum/sequences/halton.hpp"
#include "stratum/sequences/sobol.hpp"
#include "stratum/util/bits.hpp"

namespace {

/// Copies each array into storage of its own, as a device copy would be.
class Relocator {
 public:
  template <class T>
  const T* operator()(const T* data, std::size_t count) {
    auto storage = std::make_unique<unsigned char[]>(count * sizeof(T) + 1);
    std::memcpy(storage.get(), data, count * sizeof(T));
    const T* copy = reinterpret_cast<const T*>(storage.get());
    blocks_.push_back(std::move(storage));
    return copy;
  }

 private:
  std::vector<std::unique_ptr<unsigned char[]>> blocks_;
};

template <class A, class B>
void expect_same_points(const A& a, const B& b, unsigned dims) {
  for (std::uint64_t i : {0ull, 1ull, 2ull, 3ull, 1000ull, 65535ull, (1ull << 40) + 7, ~0ull})
    for (unsigned d = 0; d < dims; ++d)
      ASSERT_EQ(std::bit_cast<std::uint64_t>(a.sample(i, d)), std::bit_cast<std::uint64_t>(b.sample(i, d)))
          << "index " << i << " dim " << d;
}

}  // namespace

TEST(HostDevice, SobolViewOfRelocatedTablesEqualsSobol) {
  const stratum::Sobol sobol(40);
  Relocator relocate;
  const stratum::Sobol::View view = sobol.view(relocate);
  EXPECT_NE(sobol.table().data(), nullptr);
  EXPECT_EQ(sobol.table().size(), std::size_t{40} * 2 * (512 + 64));
  expect_same_points(sobol, view, 40);
  const stratum::HashOwenScrambler owen(7);
  for (unsigned d = 0; d < 40; ++d)
    for (std::uint64_t i : {0ull, 5ull, (1ull << 33) + 1}) EXPECT_EQ(sobol.sample(i, d, owen), view.sample(i, d, owen));
}

TEST(HostDevice, DigitScramblerViewsOfRelocatedArraysEqualTheScramblers) {
  std::vector<std::uint32_t> bases;
  for (unsigned d = 0; d < 12; ++d) bases.push_back(stratum::Halton::base(d));
  const stratum::RandomDigitPermutations permute(3, bases, 5000);  // tables and slow path both used
  const stratum::BaseBOwenScrambler owen(3, bases);
  Relocator relocate;
  expect_same_points(permute, permute.view(relocate), 12);
  expect_same_points(owen, owen.view(relocate), 12);
}

TEST(HostDevice, BitHelpersEqualStd) {
  for (std::uint64_t v : {0ull, 1ull, 2ull, 3ull, 0x80ull, 0xffffffffull, 1ull << 63, ~0ull, 0x123456789abcdefull}) {
    EXPECT_EQ(stratum::countl_zero64(v), std::countl_zero(v));
    EXPECT_EQ(stratum::countr_zero64(v), std::countr_zero(v));
    EXPECT_EQ(stratum::bit_width64(v), static_cast<int>(std::bit_width(v)));
  }
  static_assert(stratum::countl_zero64(1) == 63 && stratum::countr_zero64(0) == 64);
}
