#include "stratum/util/bits.hpp"

#include <gtest/gtest.h>

#include "stratum/util/hash.hpp"

namespace stratum {
namespace {

template <class Word>
Word naive_reverse(Word v, int width) {
  Word r = 0;
  for (int i = 0; i < width; ++i) r |= static_cast<Word>((v >> i) & 1u) << (width - 1 - i);
  return r;
}

TEST(Bits, ReverseMatchesBitByBitLoop) {
  EXPECT_EQ(reverse_bits64(1), std::uint64_t{1} << 63);
  EXPECT_EQ(reverse_bits32(1), 1u << 31);
  for (std::uint64_t k = 0; k < 1000; ++k) {
    const std::uint64_t v = hash64(k);
    ASSERT_EQ(reverse_bits64(v), naive_reverse<std::uint64_t>(v, 64));
    ASSERT_EQ(reverse_bits32(static_cast<std::uint32_t>(v)),
              naive_reverse<std::uint32_t>(static_cast<std::uint32_t>(v), 32));
    ASSERT_EQ(reverse_bits64(reverse_bits64(v)), v);
  }
}

}  // namespace
}  // namespace stratum
