/// Registry entries: Sobol' sequence and the (0,2)-sequence (Sobol'
/// dimensions 0 and 1), with the base-2 digital randomizers.
///
/// Bulk generation cuts the index range into aligned blocks of 2^k rows:
/// point m 2^k + r is base(m) ⊕ low(r), so each block is one flat pass over
/// an L1-resident table of low(r) (no serial Gray-code chain), and the next
/// block's base is one XOR per dimension away. Every chunk of rows starts
/// from a direct computation, so the output is identical for any thread
/// count. Randomizers are folded in where they are linear (XOR shift, LMS:
/// the columns themselves are scrambled), hash-based Owen scrambling works
/// on the bit-reversed words, and the result equals
/// Sobol::sample(index, dim, randomizer) bit for bit (tests/sequences/sobol_test.cpp).
/// The `bits` parameter keeps the first b digits of every coordinate (scipy's
/// Sobol(bits=b): floor(x 2^b) / 2^b); for the linear randomizers it masks
/// the columns and the shift, so it costs nothing.
#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__)
#include <immintrin.h>
#endif

#include "families.hpp"
#include "stratum/patterns/keyed_pairs.hpp"
#include "stratum/randomizers/base2.hpp"
#include "stratum/randomizers/cranley_patterson.hpp"
#include "stratum/sequences/sobol.hpp"
#include "stratum/sequences/zsobol.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/real.hpp"
#include "support.hpp"

namespace stratum::registry_families {

using namespace registry_support;

namespace {

Sobol::Order parse_order(const SamplerRequest& request) {
  return request.values.text("order") == "natural" ? Sobol::Order::natural : Sobol::Order::gray;
}

/// The `bits` parameter (1..64) as the mask of the digits it keeps.
std::uint64_t parse_digit_mask(const SamplerRequest& request) {
  const std::int64_t bits = request.values.integer("bits");
  return bits == 64 ? ~std::uint64_t{0} : ~std::uint64_t{0} << (64 - bits);
}

/// The generator matrices of the first d Sobol' dimensions in the walk's
/// layout: word [c * d + j] is column c of dimension j, after `transform`
/// (identity, bit reversal or a linear scramble; each is linear over GF(2)).
template <class Transform>
std::vector<std::uint64_t> transformed_columns(unsigned d, Transform transform) {
  std::vector<std::uint64_t> columns(std::size_t{Sobol::columns} * d);
  std::uint64_t directions[Sobol::columns];
  for (unsigned j = 0; j < d; ++j) {
    Sobol::direction_numbers(j, directions);
    for (unsigned c = 0; c < Sobol::columns; ++c) columns[std::size_t{c} * d + j] = transform(j, directions[c]);
  }
  return columns;
}

/// How rows are cut for the block kernel. Rows come in aligned blocks of
/// 2^k: block m holds the points x(m 2^k + r) = base(m) ⊕ low(r), r < 2^k,
/// with base(m) = x(m 2^k) and low(r) = C'·digits(r) (for Gray order
/// because gray(m 2^k + r) = gray(m 2^k) ⊕ gray(r)). So a block is one flat,
/// vectorizable pass over a table of 2^k · d words that stays in L1, and
/// going to the next block is one XOR per dimension (no Gray-code chain).
/// Within a block, groups of `group_rows` rows (span = group_rows · d words,
/// a multiple of 8 for d ≤ 256) line up with per-dimension constants tiled
/// to `span` words: entry t belongs to dimension t mod d. The loops over a
/// group are then whole vectors for any d, d = 2, 3 or 5 included.
struct Layout {
  unsigned d = 0;
  unsigned log_block = 0;   // k ≥ 1
  std::uint64_t block = 0;  // 2^k rows, a multiple of group_rows
  std::size_t span = 0;     // words of a group: a multiple of lcm(d, 8), ≥ 64, for d ≤ 256; else d
  unsigned group_rows = 0;  // span / d
};

Layout layout_for(unsigned d) {
  Layout layout;
  layout.d = d;
  layout.span = d <= 256 ? std::lcm(std::size_t{d}, std::size_t{8}) : d;
  if (d <= 256)
    while (layout.span < 64) layout.span *= 2;  // inner loops of 8 vectors or more
  layout.group_rows = static_cast<unsigned>(layout.span / d);
  constexpr std::uint64_t table_words = 2048;  // 16 KiB of low(r)
  const std::uint64_t rows = std::max<std::uint64_t>({2, layout.group_rows, std::bit_floor(table_words / d)});
  layout.log_block = static_cast<unsigned>(std::countr_zero(rows));
  layout.block = rows;
  return layout;
}

template <class T>
std::vector<T> tiled(const std::vector<T>& per_dimension, std::size_t span) {
  const std::size_t d = per_dimension.size();
  std::vector<T> tiles(span, per_dimension.front());
  for (std::size_t t = 0; t < span; ++t) tiles[t] = per_dimension[t % d];
  return tiles;
}

// The group loops below are compiled three times (AVX-512, AVX2, baseline
// x86-64) and picked at load time, so they vectorize where the machine allows
// it (64-bit multiplies and int64 -> double conversions are AVX-512
// instructions); hash-based Owen scrambling has a hand-written AVX-512 loop
// besides (GFNI bit reversal). Integer steps and exact conversions: every
// version gives the same bits.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define STRATUM_SOBOL_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define STRATUM_SOBOL_CLONES
#endif
#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__)
#define STRATUM_SOBOL_AVX512 1
#else
#define STRATUM_SOBOL_AVX512 0
#endif

/// What turns states (unscrambled words, or bit-reversed ones for owen_hash)
/// into output coordinates. Each table has `span` entries, tiled.
struct Finish {
  enum Kind { plain, owen_hash, rotate, owen } kind = plain;
  const std::uint64_t* addend = nullptr;                // owen_hash
  const std::uint64_t* multiplier = nullptr;            // owen_hash
  const double* shift = nullptr;                        // rotate: Cranley-Patterson shifts
  const OwenScrambler::Dimension* owen_dims = nullptr;  // owen (exact)
  std::uint64_t mask = ~std::uint64_t{0};               // digits kept (bits); plain: in the columns already
  double truncation = 0;                                // rotate with bits < 53: 2^bits, else 0

  /// The output for state x of tile entry t.
  double operator()(std::uint64_t x, std::size_t t) const noexcept {
    switch (kind) {
      case plain:
        return bits_to_double(x);
      case owen_hash:
        return bits_to_double(reverse_bits64(HashOwenScrambler::scramble_reversed(x, addend[t], multiplier[t])) & mask);
      case rotate:
        return truncated(rotated(x, shift[t]));
      case owen:
        return bits_to_double(owen_dims[t](x) & mask);
    }
    return 0;
  }
  /// CranleyPattersonRotation::operator() with its shift hashed once per
  /// dimension; the wrap is a select, not a branch (it is a coin flip).
  static double rotated(std::uint64_t x, double shift) noexcept {
    const double sum = bits_to_double(x) + shift;
    const double wrapped = sum >= 1.0 ? sum - 1.0 : sum;
    return wrapped < one_minus_epsilon_double ? wrapped : one_minus_epsilon_double;
  }
  /// floor(v 2^b) / 2^b, exact (powers of two), when bits < 53.
  double truncated(double v) const noexcept { return truncation == 0 ? v : std::floor(v * truncation) / truncation; }
};

/// out[g + t] = finish(tile[t] ⊕ low[g + t], t) for g = 0, span, .., words − span.
STRATUM_SOBOL_CLONES
void finish_groups(const Finish& finish, const std::uint64_t* __restrict tile, const std::uint64_t* __restrict low,
                   std::size_t words, std::size_t span, double* __restrict out) {
  switch (finish.kind) {
    case Finish::plain:
      for (std::size_t g = 0; g < words; g += span)
        for (std::size_t t = 0; t < span; ++t) out[g + t] = bits_to_double(tile[t] ^ low[g + t]);
      break;
    case Finish::owen_hash: {
      const std::uint64_t* __restrict addend = finish.addend;
      const std::uint64_t* __restrict multiplier = finish.multiplier;
      const std::uint64_t mask = finish.mask;
      for (std::size_t g = 0; g < words; g += span)
        for (std::size_t t = 0; t < span; ++t)
          out[g + t] = bits_to_double(
              reverse_bits64(HashOwenScrambler::scramble_reversed(tile[t] ^ low[g + t], addend[t], multiplier[t])) &
              mask);
      break;
    }
    case Finish::rotate: {
      const double* __restrict shift = finish.shift;
      if (finish.truncation != 0) {
        for (std::size_t g = 0; g < words; g += span)
          for (std::size_t t = 0; t < span; ++t) out[g + t] = finish(tile[t] ^ low[g + t], t);
        break;
      }
      for (std::size_t g = 0; g < words; g += span)
        for (std::size_t t = 0; t < span; ++t) out[g + t] = Finish::rotated(tile[t] ^ low[g + t], shift[t]);
      break;
    }
    case Finish::owen:
      for (std::size_t g = 0; g < words; g += span)
        for (std::size_t t = 0; t < span; ++t) out[g + t] = finish(tile[t] ^ low[g + t], t);
      break;
  }
}

#if STRATUM_SOBOL_AVX512
/// Words from..span − 1 of each group, which the vector loop leaves (d > 256).
[[gnu::noinline]] void finish_tails(const Finish& finish, const std::uint64_t* tile, const std::uint64_t* low,
                                    std::size_t words, std::size_t span, std::size_t from, double* out) {
  for (std::size_t g = 0; g < words; g += span)
    for (std::size_t t = from; t < span; ++t) out[g + t] = finish(tile[t] ^ low[g + t], t);
}

/// finish_groups for owen_hash with AVX-512 and GFNI: eight words per step,
/// the bit reversal is a GF(2) affine map on each byte (reverse its bits)
/// plus a byte shuffle (reverse the bytes of each word).
__attribute__((target("avx512f,avx512dq,avx512bw,gfni"))) void owen_hash_groups_gfni(
    const Finish& finish, const std::uint64_t* __restrict tile, const std::uint64_t* __restrict low, std::size_t words,
    std::size_t span, double* __restrict out) {
  const __m512i k1 = _mm512_set1_epi64(static_cast<long long>(HashOwenScrambler::k1));
  const __m512i k2 = _mm512_set1_epi64(static_cast<long long>(HashOwenScrambler::k2));
  const __m512i k3 = _mm512_set1_epi64(static_cast<long long>(HashOwenScrambler::k3));
  const __m512i reverse_byte_bits = _mm512_set1_epi64(0x8040201008040201LL);
  // Byte b of each word takes byte 7 − b of the same word.
  const long long high = 0x08090a0b0c0d0e0fLL, low_bytes = 0x0001020304050607LL;
  const __m512i reverse_bytes = _mm512_set_epi64(high, low_bytes, high, low_bytes, high, low_bytes, high, low_bytes);
  const __m512d unit = _mm512_set1_pd(0x1.0p-53);
  const __m512i mask = _mm512_set1_epi64(static_cast<long long>(finish.mask));
  const std::uint64_t* __restrict addend = finish.addend;
  const std::uint64_t* __restrict multiplier = finish.multiplier;
  const std::size_t vector_span = span / 8 * 8;
  for (std::size_t g = 0; g < words; g += span)
    for (std::size_t t = 0; t < vector_span; t += 8) {
      __m512i r = _mm512_xor_si512(_mm512_loadu_si512(tile + t), _mm512_loadu_si512(low + g + t));
      r = _mm512_xor_si512(r, _mm512_mullo_epi64(r, k1));
      r = _mm512_add_epi64(r, _mm512_loadu_si512(addend + t));
      r = _mm512_mullo_epi64(r, _mm512_loadu_si512(multiplier + t));
      r = _mm512_xor_si512(r, _mm512_mullo_epi64(r, k2));
      r = _mm512_xor_si512(r, _mm512_mullo_epi64(r, k3));
      r = _mm512_and_si512(_mm512_shuffle_epi8(_mm512_gf2p8affine_epi64_epi8(r, reverse_byte_bits, 0), reverse_bytes),
                           mask);
      // (The maskz shift: the plain one trips GCC 12's -Wuninitialized.)
      _mm512_storeu_pd(out + g + t, _mm512_mul_pd(_mm512_cvtepi64_pd(_mm512_maskz_srli_epi64(0xff, r, 11)), unit));
    }
  if (vector_span != span) finish_tails(finish, tile, low, words, span, vector_span, out);
}

bool has_avx512_gfni() {
  static const bool supported = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
                                __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("gfni");
  return supported;
}
#endif

/// The precomputed tables of one request: low(r) for r < 2^k, and carry[c]:
/// base(m) ⊕ base(m − 1) when m has c trailing zeros.
struct Tables {
  Layout layout;
  std::vector<std::uint64_t> low;    // [r * d + j]
  std::vector<std::uint64_t> carry;  // [c * d + j], c < 64 − k
};

/// Writes rows [row, row + count) of block m (rows r0.. of it), whose base
/// is tiled in `tile`; `out` points at row `row`.
void block_rows(const Tables& tables, const Finish& finish, const std::uint64_t* tile, std::uint64_t r0,
                std::uint64_t count, double* out) {
  const Layout& layout = tables.layout;
  const unsigned d = layout.d;
  const std::uint64_t* low = tables.low.data() + r0 * d;
  auto scalar_rows = [&](std::uint64_t first, std::uint64_t rows) {
    for (std::uint64_t q = first; q < first + rows; ++q)
      for (unsigned j = 0; j < d; ++j) out[q * d + j] = finish(tile[j] ^ low[q * d + j], j);
  };
  // Rows before the first whole group and after the last one go one by one.
  const std::uint64_t lead =
      std::min<std::uint64_t>(count, (layout.group_rows - r0 % layout.group_rows) % layout.group_rows);
  const std::uint64_t groups = (count - lead) / layout.group_rows;
  scalar_rows(0, lead);
  if (groups != 0) {
    const std::size_t words = groups * layout.span;
    const std::uint64_t* group_low = low + lead * d;
    double* group_out = out + lead * d;
#if STRATUM_SOBOL_AVX512
    if (finish.kind == Finish::owen_hash && has_avx512_gfni())
      owen_hash_groups_gfni(finish, tile, group_low, words, layout.span, group_out);
    else
#endif
      finish_groups(finish, tile, group_low, words, layout.span, group_out);
  }
  scalar_rows(lead + groups * layout.group_rows, count - lead - groups * layout.group_rows);
}

/// Fills n × d points: state_j(i) = offset_j ⊕ (C'_j · digits(start + i)),
/// where C'_j has the given columns, then out = finish(state). Each chunk of
/// rows starts from a direct computation, so any thread count gives the
/// same points.
PointSet walk(const SamplerRequest& request, Sobol::Order order, const std::vector<std::uint64_t>& columns,
              const std::vector<std::uint64_t>& offsets, const Finish& finish, const Layout& layout) {
  const unsigned d = request.d;
  const std::uint64_t start = request.start;
  const unsigned k = layout.log_block;
  // steps[c * d + j]: XORed into state j when the next index has c trailing
  // zeros (column c in Gray order, columns 0..c in natural order).
  std::vector<std::uint64_t> steps(columns);
  if (order == Sobol::Order::natural)
    for (unsigned c = 1; c < Sobol::columns; ++c)
      for (unsigned j = 0; j < d; ++j) steps[std::size_t{c} * d + j] ^= steps[std::size_t{c - 1} * d + j];
  Tables tables{layout, std::vector<std::uint64_t>(layout.block * d, 0),
                std::vector<std::uint64_t>(std::size_t{Sobol::columns - k} * d)};
  for (std::uint64_t r = 1; r < layout.block; ++r)
    for (unsigned j = 0; j < d; ++j)
      tables.low[r * d + j] = tables.low[(r - 1) * d + j] ^ steps[std::size_t(std::countr_zero(r)) * d + j];
  // From block m − 1 to m: digits(m 2^k) ⊕ digits((m − 1) 2^k) are bits
  // k + c and k − 1 (Gray), bits k..k + c (natural): steps[k + c] ⊕ steps[k − 1].
  for (unsigned c = 0; c + k < Sobol::columns; ++c)
    for (unsigned j = 0; j < d; ++j)
      tables.carry[std::size_t{c} * d + j] = steps[std::size_t{k + c} * d + j] ^ steps[std::size_t{k - 1} * d + j];

  PointSet points = allocate_points(*request.n, d);
  double* out = points.data.get();
  parallel_rows(*request.n, request.threads, [&](std::uint64_t begin, std::uint64_t end) {
    std::uint64_t index = start + begin;
    std::uint64_t m = index >> k;
    std::vector<std::uint64_t> base(offsets);
    const std::uint64_t digits = order == Sobol::Order::gray ? Sobol::gray_code(m << k) : m << k;
    for (std::uint64_t rest = digits; rest != 0; rest &= rest - 1) {
      const std::uint64_t* column = &columns[static_cast<std::size_t>(std::countr_zero(rest)) * d];
      for (unsigned j = 0; j < d; ++j) base[j] ^= column[j];
    }
    std::vector<std::uint64_t> tile(layout.span);
    for (std::uint64_t row = begin;;) {
      for (std::size_t t = 0, j = 0; t < layout.span; ++t, j = j + 1 == d ? 0 : j + 1) tile[t] = base[j];
      const std::uint64_t r0 = index & (layout.block - 1);
      const std::uint64_t count = std::min(layout.block - r0, end - row);
      block_rows(tables, finish, tile.data(), r0, count, out + row * d);
      row += count;
      index += count;
      if (row == end) break;
      ++m;  // index = m 2^k ≤ start + n − 1 < 2^64: m ≥ 1, so c < 64 − k
      const std::uint64_t* carry = &tables.carry[static_cast<std::size_t>(std::countr_zero(m)) * d];
      for (unsigned j = 0; j < d; ++j) base[j] ^= carry[j];
    }
  });
  return points;
}

PointSet generate_sobol(const SamplerRequest& request) {
  const unsigned d = request.d;
  const Sobol::Order order = parse_order(request);
  const Layout layout = layout_for(d);
  const Randomizer randomizer = request.randomizer;
  const std::uint64_t mask = parse_digit_mask(request);
  // Keeping the first b digits is linear: masked columns and shift (plain finish).
  const auto identity = [mask](unsigned, std::uint64_t word) { return word & mask; };
  const std::vector<std::uint64_t> zeros(d, 0);

  if (randomizer == Randomizer::none)
    return walk(request, order, transformed_columns(d, identity), zeros, Finish{}, layout);
  if (randomizer == Randomizer::xor_shift) {  // the shift commutes with the walk: start from it
    const DigitalShift shift(request.seed);
    std::vector<std::uint64_t> offsets(d);
    for (unsigned j = 0; j < d; ++j) offsets[j] = shift.shift(j) & mask;
    return walk(request, order, transformed_columns(d, identity), offsets, Finish{}, layout);
  }
  if (randomizer == Randomizer::lms) {  // L is linear: walk with scrambled columns from the shift
    const LinearMatrixScramble lms(request.seed);
    std::vector<LinearMatrixScramble::Dimension> dims;
    std::vector<std::uint64_t> offsets(d);
    for (unsigned j = 0; j < d; ++j) {
      dims.push_back(lms.dimension(j));
      offsets[j] = dims[j].shift() & mask;
    }
    const auto columns =
        transformed_columns(d, [&](unsigned j, std::uint64_t word) { return dims[j].linear(word) & mask; });
    return walk(request, order, columns, offsets, Finish{}, layout);
  }
  if (randomizer == Randomizer::owen_hash) {  // walk the bit-reversed words, scramble, reverse once
    const HashOwenScrambler owen(request.seed);
    std::vector<std::uint64_t> addends(d), multipliers(d);
    for (unsigned j = 0; j < d; ++j) {
      addends[j] = owen.dimension(j).addend();
      multipliers[j] = owen.dimension(j).multiplier();
    }
    const auto addend_tiles = tiled(addends, layout.span), multiplier_tiles = tiled(multipliers, layout.span);
    const auto reversed = [](unsigned, std::uint64_t word) { return reverse_bits64(word); };
    return walk(request, order, transformed_columns(d, reversed), zeros,
                Finish{.kind = Finish::owen_hash,
                       .addend = addend_tiles.data(),
                       .multiplier = multiplier_tiles.data(),
                       .mask = mask},
                layout);
  }
  if (randomizer == Randomizer::cp) {
    const CranleyPattersonRotation rotation(request.seed);
    std::vector<double> shifts(d);
    for (unsigned j = 0; j < d; ++j) shifts[j] = rotation.shift(j);
    const auto tiles = tiled(shifts, layout.span);
    const int bits = 64 - std::countr_zero(mask);
    const auto unmasked = [](unsigned, std::uint64_t word) { return word; };
    return walk(
        request, order, transformed_columns(d, unmasked), zeros,
        Finish{.kind = Finish::rotate, .shift = tiles.data(), .truncation = bits < 53 ? std::ldexp(1.0, bits) : 0},
        layout);
  }
  if (randomizer == Randomizer::owen) {  // 64 hashes per coordinate: scalar
    const OwenScrambler owen(request.seed);
    std::vector<OwenScrambler::Dimension> dims;
    for (unsigned j = 0; j < d; ++j) dims.push_back(owen.dimension(j));
    const auto tiles = tiled(dims, layout.span);
    const auto unmasked = [](unsigned, std::uint64_t word) { return word; };
    return walk(request, order, transformed_columns(d, unmasked), zeros,
                Finish{.kind = Finish::owen, .owen_dims = tiles.data(), .mask = mask}, layout);
  }
  throw invalid_argument("randomize", std::string(randomizer_name(randomizer)), "unknown to the Sobol generator");
}

/// The Sobol' generator: the words of Sobol::View::bits under the request's
/// randomizer (each a GF(2) map or hash of the word), masked to `bits`
/// digits; cp rotates the value and truncates it. The same points as the
/// block walk of generate_sobol, bit for bit (tests/registry/point_generator_test.cpp).
PointGenerator bind_sobol(const SamplerRequest& request) {
  const Sobol::Order order = parse_order(request);
  const auto sobol = shared_construction<Sobol>(std::pair{request.d, order == Sobol::Order::gray},
                                                [&] { return Sobol(request.d, order); });
  const std::uint64_t mask = parse_digit_mask(request);
  const auto scrambled = [&](auto randomizer) {
    return PointGenerator(request.d, [sobol, randomizer, mask](std::uint64_t i, unsigned j) {
      return bits_to_double(randomizer(sobol->view().bits(i, j), j) & mask);
    });
  };
  switch (request.randomizer) {
    case Randomizer::none:
      return scrambled([](std::uint64_t word, unsigned) { return word; });
    case Randomizer::xor_shift:
      return scrambled(DigitalShift(request.seed));
    case Randomizer::lms:
      return scrambled(LinearMatrixScramble(request.seed));
    case Randomizer::owen:
      return scrambled(OwenScrambler(request.seed));
    case Randomizer::owen_hash:
      return scrambled(HashOwenScrambler(request.seed));
    case Randomizer::cp: {
      const std::int64_t bits = request.values.integer("bits");
      const double truncation = bits < 53 ? std::ldexp(1.0, static_cast<int>(bits)) : 0;
      return PointGenerator(request.d, [sobol, rotation = CranleyPattersonRotation(request.seed), truncation](
                                           std::uint64_t i, unsigned j) {
        const double rotated = rotation(bits_to_double(sobol->view().bits(i, j)), j);
        return truncation == 0 ? rotated : std::floor(rotated * truncation) / truncation;
      });
    }
    default:
      break;
  }
  throw invalid_argument("randomize", std::string(randomizer_name(request.randomizer)),
                         "unknown to the Sobol generator");
}

// Functions, not namespace-scope objects: the registry is built on first use,
// which may come from another file's static initializer (a benchmark's
// registration), before this file's own globals are constructed.
Param order_param() {
  return params::choice("order",
                        "point order: gray (Gray code, as Boost.Random and scipy) or natural (index bits, as pbrt-v4)",
                        "gray", {"gray", "natural"});
}

Param bits_param() {
  return params::integer("bits",
                         "binary digits kept of every coordinate: floor(x 2^bits) / 2^bits after the randomizer "
                         "(scipy's Sobol bits; 64 and anything above 53 keep every digit of a double)",
                         "64", closed(1, 64));
}

/// zsobol's image (resolution) and pixel from the request; the points are
/// the pixel's n = spp samples.
struct ZSobolPixel {
  ZSobol sampler;
  std::uint32_t x = 0, y = 0;
};
ZSobolPixel zsobol_from(const SamplerRequest& request) {
  const std::int64_t resolution = request.values.integer("resolution");
  const std::vector<std::int64_t>& pixel = request.values.integers("pixel");
  for (std::int64_t c : pixel)
    require(c >= 0 && c < resolution, "pixel", std::to_string(pixel[0]) + "," + std::to_string(pixel[1]),
            "must lie in the image: coordinates in [0, resolution = " + std::to_string(resolution) + ")");
  return {ZSobol(static_cast<std::uint32_t>(resolution), *request.n, request.seed),
          static_cast<std::uint32_t>(pixel[0]), static_cast<std::uint32_t>(pixel[1])};
}

PointSet generate_zsobol(const SamplerRequest& request) {
  const ZSobolPixel z = zsobol_from(request);
  std::vector<ZSobol::Pair> pairs;
  for (unsigned p = 0; p < (request.d + 1) / 2; ++p) pairs.push_back(z.sampler.pair(p));
  return fill_index_addressable(*request.n, request.d, request.threads, [&](std::uint64_t i, unsigned j) {
    const ZSobol::Pair& pair = pairs[j / 2];
    return z.sampler.point(z.sampler.sequence_index(z.x, z.y, request.start + i, pair), pair)[j % 2];
  });
}

}  // namespace

std::vector<SamplerInfo> sobol() {
  std::vector<SamplerInfo> list;

  list.push_back({
      .name = "sobol",
      .kind = "sequence",
      .description = "Sobol' sequence (Sobol' 1967) with Joe-Kuo direction numbers (2008), 64-bit generator "
                     "matrices; unscrambled it equals boost::random::sobol and scipy's Sobol(scramble=False)",
      .min_dim = 1,
      .max_dim = Sobol::max_dimensions,
      .flags = {.index_addressable = true, .progressive = true, .zero_two_net = true, .prefix_unbiased = {"owen-hash"}},
      .properties = {"low-discrepancy", "(t,s)-sequence in base 2", "(0,2)-sequence in dims 0-1",
                     "powers of two give (t,m,s)-nets", "64-bit indices and digits"},
      .randomization = {RandomizerFamily::base2_digits, Randomizer::owen_hash},
      .counts = "any n >= 1 (powers of two give (t,m,s)-nets)",
      .params = {order_param(), bits_param()},
      .validate = nullptr,
      .count = requested_count,
      .generate = generate_sobol,  // the block walk (bulk); bind draws one point at a time
      .bind = bind_sobol,
      .keyed_pairs = keyed_under<SobolOwenHashPairs>(Randomizer::owen_hash),
  });

  list.push_back({
      .name = "zsobol",
      .kind = "pattern",
      .description = "the spp samples of one pixel of a blue-noise-error image sampler (Ahmed & Wonka 2020; pbrt-v4's "
                     "ZSobolSampler): one Owen-scrambled Sobol' sequence along a Morton curve over the pixels, each "
                     "base-4 digit randomly permuted per dimension pair; render --sampler zsobol uses it per pixel",
      .min_dim = 1,
      .max_dim = 64,
      .flags = {.frames_continue = true, .self_randomized = true},
      .properties = {"(0,m,2)-net per pixel in each dimension pair", "blue-noise error across pixels"},
      .randomization = {RandomizerFamily::seeded_owen_hash, Randomizer::owen_hash},
      .counts = "n = spp, a power of 2 up to 2^24",
      .params = {params::integers("pixel", "the pixel x,y whose samples these are", "0,0", at_least(0), {2, 2}),
                 params::integer("resolution", "the image's larger side in pixels (sets the Morton levels)", "1",
                                 closed(1, ZSobol::max_resolution))},
      .validate = [](const SamplerRequest& request) { zsobol_from(request); },
      .count = requested_count,
      .generate = generate_zsobol,
      .zsobol_image = [](std::uint32_t resolution, std::uint64_t spp,
                         std::uint64_t seed) { return ZSobol(resolution, spp, seed); },
  });

  list.push_back({
      .name = "zero-two",
      .kind = "sequence",
      .description = "the (0,2)-sequence in base 2: Sobol' dimensions 0 and 1 (van der Corput and its "
                     "companion); every 2^k prefix has one point in each 2^-i x 2^-(k-i) box",
      .min_dim = 2,
      .max_dim = 2,
      .flags = {.index_addressable = true, .progressive = true, .zero_two_net = true},
      .properties = {"(0,2)-sequence", "(0,m,2)-net at every power of two"},
      .randomization = {RandomizerFamily::base2_digits, Randomizer::owen_hash},
      .counts = "any n >= 1 (powers of two give (0,m,2)-nets)",
      .params = {order_param(), bits_param()},
      .validate = nullptr,
      .count = requested_count,
      .generate = generate_sobol,  // the block walk (bulk); bind draws one point at a time
      .bind = bind_sobol,
      .keyed_pairs = keyed_under<SobolOwenHashPairs>(Randomizer::owen_hash),  // Sobol's dimensions 0 and 1
  });

  return list;
}

}  // namespace stratum::registry_families
