/// Registry entries: Sobol' sequence and the (0,2)-sequence (Sobol'
/// dimensions 0 and 1), with the base-2 digital randomizers.
///
/// Bulk generation walks the sequence in Gray-code order: within a chunk of
/// rows each coordinate is updated by x ^= step[ctz(i)] (one XOR), and every
/// chunk starts from a direct computation, so the output is identical for
/// any thread count. Randomizers are folded in where they are linear (XOR
/// shift, LMS: the steps themselves are scrambled), hash-based Owen
/// scrambling walks the bit-reversed words, and the result equals
/// Sobol::sample(index, dim, randomizer) bit for bit (tests/sequences/sobol_test.cpp).
#include <algorithm>
#include <bit>
#include <string>
#include <vector>

#include "families.hpp"
#include "stratum/randomizers/base2.hpp"
#include "stratum/randomizers/cranley_patterson.hpp"
#include "stratum/sequences/sobol.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/real.hpp"
#include "support.hpp"

namespace stratum::registry_families {

using namespace registry_support;

namespace {

Sobol::Order parse_order(const SamplerRequest& request) {
  const auto text = param_text(request, "order");
  if (!text || *text == "gray") return Sobol::Order::gray;
  if (*text == "natural") return Sobol::Order::natural;
  throw invalid_argument("order", text->empty() ? "''" : *text,
                         "must be gray (Boost and scipy order) or natural (pbrt-v4 order)");
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

// The kernels below are compiled three times (AVX-512, AVX2, baseline x86-64)
// and picked at load time, so the row loops vectorize where the machine
// allows it (64-bit multiplies and int64 -> double conversions are AVX-512
// instructions). Integer steps and exact conversions: every clone gives the
// same bits.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define STRATUM_SOBOL_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define STRATUM_SOBOL_CLONES
#endif

/// Coordinates per block of the walk: a block's states are collected row by
/// row, then turned into output in one flat loop, which vectorizes for any d
/// (d = 2 included). Per-dimension constants are tiled to the block's length.
constexpr unsigned block_coordinates = 1024;
unsigned block_rows(unsigned d) { return std::max(1u, block_coordinates / d); }

/// What turns walk states into output coordinates; per-dimension constants
/// are tiled: entry k belongs to dimension k mod d (block_rows(d) · d entries).
struct Finish {
  enum Kind { plain, owen_hash, rotate } kind = plain;
  const HashOwenScrambler::Dimension* owen = nullptr;  // owen_hash: states are bit-reversed words
  const double* shift = nullptr;                       // rotate: Cranley-Patterson shifts
};

template <class T>
std::vector<T> tiled(const std::vector<T>& per_dimension) {
  const std::size_t d = per_dimension.size();
  std::vector<T> tiles(block_rows(static_cast<unsigned>(d)) * d, per_dimension.front());
  for (std::size_t k = 0; k < tiles.size(); ++k) tiles[k] = per_dimension[k % d];
  return tiles;
}

/// Rows [begin, end) from the states x at row `begin` (x ^= steps[ctz(start
/// + i)] before row i). `states` holds block_rows(d) · d words.
STRATUM_SOBOL_CLONES
void walk_rows(const Finish& finish, std::uint64_t* __restrict x, std::uint64_t* __restrict states,
               const std::uint64_t* __restrict steps, unsigned d, std::uint64_t start, std::uint64_t begin,
               std::uint64_t end, double* __restrict out) {
  const std::uint64_t rows_per_block = block_rows(d);
  for (std::uint64_t i = begin; i < end; i += rows_per_block) {
    const std::uint64_t rows = std::min(rows_per_block, end - i);
    const std::uint64_t first = i == begin ? 1 : 0;  // row `begin` needs no step
    if (d < 8) {  // few dimensions: walk each one down the block, no short inner loops
      for (unsigned j = 0; j < d; ++j) {
        std::uint64_t xj = x[j];
        if (first) states[j] = xj;
        for (std::uint64_t r = first; r < rows; ++r) {
          xj ^= steps[static_cast<std::size_t>(std::countr_zero(start + i + r)) * d + j];
          states[r * d + j] = xj;
        }
        x[j] = xj;
      }
    } else {
      if (first)
        for (unsigned j = 0; j < d; ++j) states[j] = x[j];
      for (std::uint64_t r = first; r < rows; ++r) {
        const std::uint64_t* __restrict step = steps + static_cast<std::size_t>(std::countr_zero(start + i + r)) * d;
        std::uint64_t* __restrict row = states + r * d;
        for (unsigned j = 0; j < d; ++j) row[j] = x[j] ^= step[j];
      }
    }
    const std::size_t count = rows * d;
    double* __restrict o = out + i * d;
    if (finish.kind == Finish::plain) {
      for (std::size_t k = 0; k < count; ++k) o[k] = bits_to_double(states[k]);
    } else if (finish.kind == Finish::owen_hash) {
      const HashOwenScrambler::Dimension* __restrict owen = finish.owen;
      for (std::size_t k = 0; k < count; ++k)
        o[k] = bits_to_double(reverse_bits64(owen[k].scramble_reversed(states[k])));
    } else {
      // CranleyPattersonRotation::operator() with its shift hashed once per
      // dimension; the wrap is a select, not a branch (it is a coin flip).
      const double* __restrict shift = finish.shift;
      for (std::size_t k = 0; k < count; ++k) {
        const double rotated = bits_to_double(states[k]) + shift[k];
        const double wrapped = rotated >= 1.0 ? rotated - 1.0 : rotated;
        o[k] = wrapped < one_minus_epsilon_double ? wrapped : one_minus_epsilon_double;
      }
    }
  }
}

/// Fills n × d points: state_j(i) = offset_j ⊕ (C'_j · digits(start + i)),
/// where C'_j has the given columns; rows(x, steps, begin, end, out) turns
/// the states at row `begin` into rows [begin, end). Each chunk of rows
/// starts from this direct computation, so any thread count gives the same
/// points.
template <class Rows>
PointSet walk(const SamplerRequest& request, Sobol::Order order, const std::vector<std::uint64_t>& columns,
              const std::vector<std::uint64_t>& offsets, const Rows& rows) {
  const unsigned d = request.d;
  const std::uint64_t start = request.start;
  // steps[c * d + j]: XORed into state j when the next index has c trailing zeros.
  std::vector<std::uint64_t> steps(columns);
  if (order == Sobol::Order::natural)
    for (unsigned c = 1; c < Sobol::columns; ++c)
      for (unsigned j = 0; j < d; ++j) steps[std::size_t{c} * d + j] ^= steps[std::size_t{c - 1} * d + j];

  PointSet points = allocate_points(*request.n, d);
  double* out = points.data.get();
  parallel_rows(*request.n, request.threads, [&](std::uint64_t begin, std::uint64_t end) {
    std::vector<std::uint64_t> state(offsets);
    const std::uint64_t index = start + begin;
    const std::uint64_t digits = order == Sobol::Order::gray ? Sobol::gray_code(index) : index;
    for (std::uint64_t rest = digits; rest != 0; rest &= rest - 1) {
      const std::uint64_t* column = &columns[static_cast<std::size_t>(std::countr_zero(rest)) * d];
      for (unsigned j = 0; j < d; ++j) state[j] ^= column[j];
    }
    rows(state.data(), steps.data(), begin, end, out);
  });
  return points;
}

/// rows() for walk_rows with a given finish.
auto vector_rows(const SamplerRequest& request, const Finish& finish) {
  return [&request, finish](std::uint64_t* x, const std::uint64_t* steps, std::uint64_t begin, std::uint64_t end,
                            double* out) {
    std::vector<std::uint64_t> states(std::size_t{block_rows(request.d)} * request.d);
    walk_rows(finish, x, states.data(), steps, request.d, request.start, begin, end, out);
  };
}

PointSet generate_sobol(const SamplerRequest& request) {
  const unsigned d = request.d;
  const Sobol::Order order = parse_order(request);
  const std::string& randomize = request.randomize;
  const auto identity = [](unsigned, std::uint64_t word) { return word; };
  const std::vector<std::uint64_t> zeros(d, 0);
  const auto plain = vector_rows(request, Finish{});

  if (randomize == "none") return walk(request, order, transformed_columns(d, identity), zeros, plain);
  if (randomize == "xor") {  // the shift commutes with the walk: start from it
    const DigitalShift shift(request.seed);
    std::vector<std::uint64_t> offsets(d);
    for (unsigned j = 0; j < d; ++j) offsets[j] = shift.shift(j);
    return walk(request, order, transformed_columns(d, identity), offsets, plain);
  }
  if (randomize == "lms") {  // L is linear: walk with scrambled columns from the shift
    const LinearMatrixScramble lms(request.seed);
    std::vector<LinearMatrixScramble::Dimension> dims;
    std::vector<std::uint64_t> offsets(d);
    for (unsigned j = 0; j < d; ++j) {
      dims.push_back(lms.dimension(j));
      offsets[j] = dims[j].shift();
    }
    const auto columns = transformed_columns(d, [&](unsigned j, std::uint64_t word) { return dims[j].linear(word); });
    return walk(request, order, columns, offsets, plain);
  }
  if (randomize == "owen-hash") {  // walk the bit-reversed words, scramble, reverse once
    const HashOwenScrambler owen(request.seed);
    std::vector<HashOwenScrambler::Dimension> dims;
    for (unsigned j = 0; j < d; ++j) dims.push_back(owen.dimension(j));
    const auto tiles = tiled(dims);
    const auto reversed = [](unsigned, std::uint64_t word) { return reverse_bits64(word); };
    return walk(request, order, transformed_columns(d, reversed), zeros,
                vector_rows(request, Finish{.kind = Finish::owen_hash, .owen = tiles.data()}));
  }
  if (randomize == "cp") {
    const CranleyPattersonRotation rotation(request.seed);
    std::vector<double> shifts(d);
    for (unsigned j = 0; j < d; ++j) shifts[j] = rotation.shift(j);
    const auto tiles = tiled(shifts);
    return walk(request, order, transformed_columns(d, identity), zeros,
                vector_rows(request, Finish{.kind = Finish::rotate, .shift = tiles.data()}));
  }
  if (randomize == "owen") {  // 64 hashes per coordinate: scalar
    const OwenScrambler owen(request.seed);
    std::vector<OwenScrambler::Dimension> dims;
    for (unsigned j = 0; j < d; ++j) dims.push_back(owen.dimension(j));
    return walk(request, order, transformed_columns(d, identity), zeros,
                [&](std::uint64_t* x, const std::uint64_t* steps, std::uint64_t begin, std::uint64_t end, double* out) {
                  for (std::uint64_t i = begin;;) {
                    for (unsigned j = 0; j < d; ++j) out[i * d + j] = bits_to_double(dims[j](x[j]));
                    if (++i == end) break;
                    const std::uint64_t* step =
                        steps + static_cast<std::size_t>(std::countr_zero(request.start + i)) * d;
                    for (unsigned j = 0; j < d; ++j) x[j] ^= step[j];
                  }
                });
  }
  throw invalid_argument("randomize", randomize, "unknown to the Sobol generator");
}

const ParamSpec order_param{
    "order", "point order: gray (Gray code, as Boost.Random and scipy) or natural (index bits, as pbrt-v4)", "gray"};

void validate_order(const SamplerRequest& request) { parse_order(request); }

}  // namespace

std::vector<SamplerInfo> sobol() {
  std::vector<SamplerInfo> list;
  const auto requested_count = [](const SamplerRequest& request) -> std::optional<std::uint64_t> { return request.n; };

  list.push_back({
      .name = "sobol",
      .kind = "sequence",
      .description = "Sobol' sequence (Sobol' 1967) with Joe-Kuo direction numbers (2008), 64-bit generator "
                     "matrices; unscrambled it equals boost::random::sobol and scipy's Sobol(scramble=False)",
      .min_dim = 1,
      .max_dim = Sobol::max_dimensions,
      .properties = {"index-addressable", "progressive", "low-discrepancy", "(t,s)-sequence in base 2",
                     "(0,2)-sequence in dims 0-1", "powers of two give (t,m,s)-nets", "64-bit indices and digits"},
      .randomizers = {"owen-hash", "none", "owen", "xor", "lms", "cp"},
      .counts = "any n >= 1 (powers of two give (t,m,s)-nets)",
      .params = {order_param},
      .validate = validate_order,
      .count = requested_count,
      .generate = generate_sobol,
  });

  list.push_back({
      .name = "zero-two",
      .kind = "sequence",
      .description = "the (0,2)-sequence in base 2: Sobol' dimensions 0 and 1 (van der Corput and its "
                     "companion); every 2^k prefix has one point in each 2^-i x 2^-(k-i) box",
      .min_dim = 2,
      .max_dim = 2,
      .properties = {"index-addressable", "progressive", "(0,2)-sequence", "(0,m,2)-net at every power of two"},
      .randomizers = {"owen-hash", "none", "owen", "xor", "lms"},
      .counts = "any n >= 1 (powers of two give (0,m,2)-nets)",
      .params = {order_param},
      .validate = validate_order,
      .count = requested_count,
      .generate = generate_sobol,
  });

  return list;
}

}  // namespace stratum::registry_families
