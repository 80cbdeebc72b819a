/// Registry entries of the radical-inverse sequences: Halton and Hammersley,
/// each with the base-b randomizers of include/stratum/randomizers/.
///
/// Randomizers (the first is the default):
///  - permute: random digit permutations (Owen 2017; scipy's scramble=True);
///  - none: the deterministic construction;
///  - owen: nested uniform scrambling in each base (Owen 1995), slower;
///  - xor: base-b digital shift;
///  - cp: Cranley–Patterson rotation of the unscrambled points.
/// Hammersley takes the same list and also defaults to permute; the
/// coordinates 1..d−1 are Halton's coordinates 0..d−2 with the same seed and
/// randomizer (cp aside). Coordinate 0, i/N, is randomized by every
/// randomizer but none, so each point is uniform and estimates are
/// unbiased: cp rotates it (exactly Latin for any N); permute and xor apply
/// a base-2 digital shift to its 64-bit binary fraction (a random digit
/// permutation in base 2 is a flip), owen nested uniform scrambling in base
/// 2. These map dyadic intervals onto dyadic intervals, so at N = 2^k i/N
/// stays Latin and the (0, k, 2)-net of (i/N, φ_2(i)) survives; at other N
/// coordinate 0 is uniform but no longer exactly one point per 1/N.
/// Faure's (0, s)-sequence takes the same randomizers, defaulting to owen:
/// each acts on the point's digits (the digit word), so nets stay nets.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>

#include "families.hpp"
#include "stratum/randomizers/base2.hpp"
#include "stratum/randomizers/cranley_patterson.hpp"
#include "stratum/randomizers/digit_permutation.hpp"
#include "stratum/randomizers/digital_shift_base_b.hpp"
#include "stratum/randomizers/owen_base_b.hpp"
#include "stratum/sequences/faure.hpp"
#include "stratum/registry/halton_pair_tables.hpp"
#include "stratum/sequences/halton.hpp"
#include "stratum/sequences/radical_inverse.hpp"
#include "support.hpp"

namespace stratum::registry_families {

using namespace registry_support;

/// The first `count` primes: Halton's bases.
static std::vector<std::uint32_t> prime_bases(unsigned count) {
  std::vector<std::uint32_t> bases(count);
  for (unsigned j = 0; j < count; ++j) bases[j] = prime(j);
  return bases;
}

/// Fills an n × d PointSet column by column within blocks of rows, so that
/// a tabulated randomizer writes runs of consecutive indices;
/// column(first_row, rows, dim, out) writes out[k·d] for k < rows. Rows
/// depend only on their index: identical for any thread count.
template <class ColumnFn>
static PointSet fill_by_columns(std::uint64_t n, unsigned d, unsigned threads, const ColumnFn& column) {
  PointSet points = allocate_points(n, d);
  double* out = points.data.get();
  const std::uint64_t block = std::clamp<std::uint64_t>(2048 / d, 16, 1024);  // a block stays in L1/L2
  parallel_rows(n, threads, [&](std::uint64_t begin, std::uint64_t end) {
    for (std::uint64_t row = begin; row < end; row += block) {
      const auto rows = static_cast<std::size_t>(std::min(block, end - row));
      for (unsigned j = 0; j < d; ++j) column(row, rows, j, out + row * d + j);
    }
  });
  return points;
}

/// fill_by_columns for a per-value sample(index, dim).
template <class SampleFn>
static PointSet fill_each(std::uint64_t n, unsigned d, unsigned threads, const SampleFn& sample) {
  return fill_by_columns(n, d, threads, [&](std::uint64_t row, std::size_t rows, unsigned j, double* out) {
    for (std::size_t k = 0; k < rows; ++k) out[k * d] = sample(row + k, j);
  });
}

/// The one dispatch of the base-b digit randomizers (family base_b_digits):
/// calls use(scrambler) with the scrambler of request.randomizer (permute,
/// xor or owen) over `bases` for digit words up to `max_word`, an rvalue that
/// use may keep; nullopt for none and cp, which act on the construction's
/// value, not its digits.
template <class Use>
static auto with_digit_scrambler(const SamplerRequest& request, const std::vector<std::uint32_t>& bases,
                                 std::uint64_t max_word, const Use& use)
    -> std::optional<decltype(use(BaseBOwenScrambler(request.seed, bases)))> {
  switch (request.randomizer) {
    case Randomizer::permute:
      return use(RandomDigitPermutations(request.seed, bases, max_word));
    case Randomizer::xor_shift:
      return use(BaseBDigitalShift(request.seed, bases, max_word));
    case Randomizer::owen:
      return use(BaseBOwenScrambler(request.seed, bases));
    default:
      return std::nullopt;
  }
}

/// Base-b owen as a SeededGenerator: the scrambler's seed-independent part
/// (bases, digit weights) built once, a seed's keys as the state.
/// digits(index, dim) is the digit word the scrambler reads: the index for
/// Halton, its word under the generator matrices for Faure.
template <class Digits>
class OwenSeeded final : public SeededGenerator {
 public:
  OwenSeeded(const std::vector<std::uint32_t>& bases, Digits digits)
      : scrambler_(0, bases), digits_(std::move(digits)) {}
  std::size_t state_words() const noexcept override { return scrambler_.key_count(); }
  void seed(std::uint64_t seed, unsigned coordinates, std::uint64_t* state) const noexcept override {
    scrambler_.keys_for(seed, state, coordinates);
  }
  void point(const std::uint64_t* state, std::uint64_t index, unsigned coordinates,
             double* out) const noexcept override {
    points(state, index, 1, coordinates, out);
  }
  void points(const std::uint64_t* state, std::uint64_t first, std::uint64_t count, unsigned coordinates,
              double* out) const noexcept override {
    const BaseBOwenScrambler::View view = scrambler_.view(state);
    for (std::uint64_t k = 0; k < count; ++k, out += coordinates)
      for (unsigned j = 0; j < coordinates; ++j) out[j] = view.sample(digits_(first + k, j), j);
  }

 private:
  BaseBOwenScrambler scrambler_;
  Digits digits_;
};

/// out[k·stride] = scrambler.sample(first + k, dim) for k < count: the
/// tabulated scramblers' fill where they have one.
template <class Scrambler>
static void fill_scrambled(const Scrambler& scrambler, std::uint64_t first, std::size_t count, unsigned dim,
                           double* out, std::size_t stride) {
  if constexpr (requires { scrambler.fill(first, count, dim, out, stride); }) {
    scrambler.fill(first, count, dim, out, stride);
  } else {
    for (std::size_t k = 0; k < count; ++k) out[k * stride] = scrambler.sample(first + k, dim);
  }
}

/// Halton's bases: the `bases` parameter when given (one per dimension),
/// else the first d primes.
static std::vector<std::uint32_t> halton_bases(const SamplerRequest& request) {
  if (!request.values.has("bases")) return prime_bases(request.d);
  const auto& given = request.values.integers("bases");
  return {given.begin(), given.end()};
}

static void validate_halton(const SamplerRequest& request) {
  if (!request.values.has("bases")) return;
  const std::size_t count = request.values.integers("bases").size();
  if (count != request.d)
    throw invalid_argument("bases", "(" + std::to_string(count) + (count == 1 ? " value)" : " values)"),
                           "give one base per dimension: d = " + std::to_string(request.d));
}

/// Radical inverses in any bases, one per dimension: Halton's construction
/// for the `bases` parameter.
struct RadicalInverses {
  std::vector<std::uint32_t> bases;
  std::vector<std::uint64_t> reciprocals;
  explicit RadicalInverses(std::vector<std::uint32_t> given) : bases(std::move(given)), reciprocals(bases.size()) {
    for (std::size_t j = 0; j < bases.size(); ++j) reciprocals[j] = radical_inverse_reciprocal(bases[j]);
  }
  double sample(std::uint64_t index, unsigned dim) const {
    return radical_inverse(bases[dim], index, reciprocals[dim]);
  }
};

/// Halton's unscrambled constructions, for generate_rotated and bind_rotated (none, cp).
static RadicalInverses radical_inverses_of(const SamplerRequest& request) {
  return RadicalInverses(halton_bases(request));
}
static Halton halton_of(const SamplerRequest& request) { return Halton(request.d); }

/// Halton points with the request's randomizer, indices start .. start+n−1.
static PointSet generate_halton(const SamplerRequest& request) {
  const std::uint64_t n = *request.n, start = request.start;
  const unsigned d = request.d;
  const std::vector<std::uint32_t> bases = halton_bases(request);
  if (request.randomizer == Randomizer::permute && bases == std::vector<std::uint32_t>{2, 3} &&
      start + n <= HaltonPairTables::max_points) {
    // The engine for small 2D sets: the permutations the n points use, not
    // RandomDigitPermutations' tables (equal bit for bit: halton_pair_tables_test).
    PointSet points{n, 2, std::make_unique<double[]>(2 * n)};
    HaltonPairTables().fill(request.seed, start, n, points.data.get());
    return points;
  }
  auto scrambled = with_digit_scrambler(request, bases, start + n - 1, [&](const auto& scrambler) {
    return fill_by_columns(n, d, request.threads, [&](std::uint64_t row, std::size_t rows, unsigned j, double* out) {
      fill_scrambled(scrambler, start + row, rows, j, out, d);
    });
  });
  if (scrambled) return std::move(*scrambled);
  if (request.values.has("bases")) return generate_rotated(radical_inverses_of)(request);
  return generate_rotated(halton_of)(request);
}

/// Halton's generator: the same points as generate_halton, one at a time.
static PointGenerator bind_halton(const SamplerRequest& request) {
  const std::vector<std::uint32_t> bases = halton_bases(request);
  const std::uint64_t max_index = request.start + *request.n - 1;
  auto scrambled = with_digit_scrambler(request, bases, max_index, [&](auto&& scrambler) {
    using Scrambler = std::decay_t<decltype(scrambler)>;
    return plain_generator(request.d, std::make_shared<const Scrambler>(std::forward<Scrambler>(scrambler)));
  });
  if (scrambled) return std::move(*scrambled);
  if (request.values.has("bases")) return bind_rotated(radical_inverses_of)(request);
  return bind_rotated(halton_of)(request);
}

/// Halton's SeededGenerator under owen (the same points as bind_halton's).
static std::shared_ptr<const SeededGenerator> seeded_halton(const SamplerRequest& request) {
  if (request.randomizer != Randomizer::owen) return nullptr;
  const auto index = [](std::uint64_t i, unsigned) { return i; };
  return std::make_shared<const OwenSeeded<decltype(index)>>(halton_bases(request), index);
}

/// i/N as a 64-bit binary fraction, floor(i · 2^64 / N): exact at N = 2^k.
static std::uint64_t fraction_bits(std::uint64_t i, std::uint64_t n) {
  return static_cast<std::uint64_t>((static_cast<unsigned __int128>(i) << 64) / n);
}

/// Hammersley's coordinate 0 under permute, xor and owen: i/N's binary
/// digits scrambled with a key of its own (independent of the radical
/// inverses' scramblers). In base 2 a random permutation of each digit is a
/// random flip, so permute and xor are the same digital shift; owen is
/// nested uniform scrambling.
struct HammersleyFirst {
  static constexpr std::uint64_t tag = 0x68616d30ULL;  // "ham0"
  std::uint64_t n;
  std::uint64_t shift;  ///< the digital shift's word (permute, xor)
  OwenScrambler::Dimension nested;
  bool owen;
  HammersleyFirst(std::uint64_t count, std::uint64_t seed, Randomizer randomizer)
      : n(count),
        shift(shift_of(seed)),
        nested(OwenScrambler(hash64(seed, tag)).dimension(0)),
        owen(randomizer == Randomizer::owen) {}
  static std::uint64_t shift_of(std::uint64_t seed) noexcept { return DigitalShift(hash64(seed, tag)).shift(0); }
  /// i/N under the digital shift `shift` (permute, xor).
  static double shifted(std::uint64_t i, std::uint64_t n, std::uint64_t shift) noexcept {
    return bits_to_double(fraction_bits(i, n) ^ shift);
  }
  double operator()(std::uint64_t i) const noexcept {
    return owen ? bits_to_double(nested(fraction_bits(i, n))) : shifted(i, n, shift);
  }
};

static Hammersley hammersley_of(const SamplerRequest& request) { return Hammersley(*request.n, request.d); }

/// Hammersley points: coordinate 0 is i/N randomized in base 2 (see the top
/// of this file), the others are Halton's coordinates 0..d−2 under the same
/// randomizer.
static PointSet generate_hammersley(const SamplerRequest& request) {
  const std::uint64_t n = *request.n;
  const unsigned d = request.d;
  const Randomizer randomizer = request.randomizer;
  if (randomizer == Randomizer::cp || randomizer == Randomizer::none) return generate_rotated(hammersley_of)(request);
  const HammersleyFirst first(n, request.seed, randomizer);
  if (d == 1) return fill_each(n, d, request.threads, [&](std::uint64_t i, unsigned) { return first(i); });
  return std::move(*with_digit_scrambler(request, prime_bases(d - 1), n - 1, [&](const auto& scrambler) {
    return fill_by_columns(n, d, request.threads, [&](std::uint64_t row, std::size_t rows, unsigned j, double* out) {
      if (j > 0) return fill_scrambled(scrambler, row, rows, j - 1, out, d);
      for (std::size_t k = 0; k < rows; ++k) out[k * d] = first(row + k);
    });
  }));
}

/// Hammersley's generator: the same points as generate_hammersley, one at a time.
static PointGenerator bind_hammersley(const SamplerRequest& request) {
  const std::uint64_t n = *request.n;
  const unsigned d = request.d;
  if (request.randomizer == Randomizer::cp || request.randomizer == Randomizer::none)
    return bind_rotated(hammersley_of)(request);
  const HammersleyFirst first(n, request.seed, request.randomizer);
  if (d == 1) return PointGenerator(1, [first](std::uint64_t i, unsigned) { return first(i); });
  return std::move(*with_digit_scrambler(request, prime_bases(d - 1), n - 1, [&](auto&& scrambler) {
    using Scrambler = std::decay_t<decltype(scrambler)>;
    auto shared = std::make_shared<const Scrambler>(std::forward<Scrambler>(scrambler));
    return PointGenerator(
        d, [shared, first](std::uint64_t i, unsigned j) { return j == 0 ? first(i) : shared->sample(i, j - 1); });
  }));
}

/// Hammersley's 1D and 2D sets under permute, its default (a renderer's
/// pixel sets) as a SeededGenerator: coordinate 0 is i/N under a digital
/// shift, coordinate 1 Halton's base-2 coordinate under random digit
/// permutations, which in base 2 are one word of flips (HaltonPairTables);
/// a seed's state is those two words. nullptr otherwise (bind's path).
class HammersleyPairSeeded final : public SeededGenerator {
 public:
  explicit HammersleyPairSeeded(std::uint64_t n) : n_(n) {}
  std::size_t state_words() const noexcept override { return 2; }
  void seed(std::uint64_t seed, unsigned coordinates, std::uint64_t* state) const noexcept override {
    state[0] = HammersleyFirst::shift_of(seed);
    if (coordinates > 1) state[1] = HaltonPairTables::base2_word(seed);
  }
  void point(const std::uint64_t* state, std::uint64_t index, unsigned coordinates,
             double* out) const noexcept override {
    out[0] = HammersleyFirst::shifted(index, n_, state[0]);
    if (coordinates > 1) out[1] = digits_detail::fraction_to_double(reverse_bits64(index) ^ state[1]);
  }

 private:
  std::uint64_t n_;
};
static std::shared_ptr<const SeededGenerator> seeded_hammersley(const SamplerRequest& request) {
  if (request.randomizer != Randomizer::permute || request.d > 2) return nullptr;
  return std::make_shared<const HammersleyPairSeeded>(*request.n);
}

/// Faure's generator: the request's randomizer applied to the digit words
/// of each index (the registry fills sets from it).
static PointGenerator bind_faure(const SamplerRequest& request) {
  const unsigned d = request.d;
  const auto shared = shared_construction<Faure>(d, [d] { return Faure(d); });
  const Faure& faure = *shared;
  const std::vector<std::uint32_t> bases(d, faure.base());
  // Digit words of indices < b^k are < b^k: the tables' range.
  unsigned __int128 bound = 1;
  for (std::uint64_t last = request.start + *request.n - 1; last != 0; last /= faure.base()) bound *= faure.base();
  const std::uint64_t max_word = bound > ~std::uint64_t{0} ? ~std::uint64_t{0} : static_cast<std::uint64_t>(bound - 1);
  // The lambdas hold the shared construction, never a copy of its matrices.
  auto scrambled = with_digit_scrambler(request, bases, max_word, [&](auto&& scrambler) {
    using Scrambler = std::decay_t<decltype(scrambler)>;
    auto scrambling = std::make_shared<const Scrambler>(std::forward<Scrambler>(scrambler));
    return PointGenerator(d, [scrambling, shared](std::uint64_t i, unsigned j) {
      return scrambling->sample(shared->digit_word(i, j), j);
    });
  });
  if (scrambled) return std::move(*scrambled);
  return rotated_generator(request, shared);
}

/// Faure's SeededGenerator under owen (the same points as bind_faure's).
static std::shared_ptr<const SeededGenerator> seeded_faure(const SamplerRequest& request) {
  if (request.randomizer != Randomizer::owen) return nullptr;
  const unsigned d = request.d;
  const auto shared = shared_construction<Faure>(d, [d] { return Faure(d); });
  const auto words = [shared](std::uint64_t i, unsigned j) { return shared->digit_word(i, j); };
  return std::make_shared<const OwenSeeded<decltype(words)>>(std::vector<std::uint32_t>(d, shared->base()), words);
}

std::vector<SamplerInfo> sequences() {
  std::vector<SamplerInfo> list;

  list.push_back({
      .name = "halton",
      .kind = "sequence",
      .description = "Halton points: radical inverse in the d-th prime base, or in the given bases (Halton 1960; "
                     "d = 1, bases=b: van der Corput's sequence in base b); by default scrambled by random digit "
                     "permutations (Owen 2017, scipy's scramble=True)",
      .min_dim = 1,
      .max_dim = Halton::max_dimensions,
      .flags = {.index_addressable = true, .progressive = true},
      .properties = {"low-discrepancy", "mixed-base elementary intervals (none, permute, owen, xor)"},
      .randomization = {RandomizerFamily::base_b_digits, Randomizer::permute},
      .counts = "any n >= 1",
      .params = {params::integers("bases",
                                  "one radical-inverse base per dimension (default: the first d primes); "
                                  "pairwise coprime bases give a low-discrepancy set, a repeated base a diagonal",
                                  "", closed(2, digits_detail::max_base), Length{1, Halton::max_dimensions})},
      .validate = validate_halton,
      .count = requested_count,
      .generate = generate_halton,  // column fills of the tabulated scramblers
      .bind = bind_halton,
      .seeded = seeded_halton,
      .pair_tables = [](Randomizer randomizer) -> std::optional<HaltonPairTables> {
        if (randomizer != Randomizer::permute) return std::nullopt;
        return HaltonPairTables();
      },
  });

  list.push_back({
      .name = "hammersley",
      .kind = "pattern",
      .description = "Hammersley points (i/N, phi_2(i), phi_3(i), ...) (Hammersley 1964); by default the radical "
                     "inverses are scrambled by random digit permutations and i/N by a base-2 digital shift (owen: "
                     "nested scrambling; cp: rotation), so every randomizer but none is unbiased",
      .min_dim = 1,
      .max_dim = Hammersley::max_dimensions,
      .flags = {.index_addressable = true},
      .properties = {"low-discrepancy", "Latin in dimension 0 (none, cp; permute, xor, owen at N = 2^k)",
                     "elementary intervals at N = b^k (none; permute, owen, xor: of (i/N, phi_2(i)) at N = 2^k)",
                     "unbiased (but none)"},
      .randomization = {RandomizerFamily::base_b_digits, Randomizer::permute},
      .counts = "any n >= 1",
      .params = {},
      .validate = nullptr,
      .count = requested_count,
      .generate = generate_hammersley,
      .bind = bind_hammersley,
      .seeded = seeded_hammersley,
  });

  list.push_back({
      .name = "faure",
      .kind = "sequence",
      .description = "Faure's (0,s)-sequence in the smallest prime base b >= s, generator matrices the powers of "
                     "the Pascal matrix mod b (Faure 1982); by default Owen-scrambled in base b (Owen 1995)",
      .min_dim = 1,
      .max_dim = Faure::max_dimensions,
      .flags = {.index_addressable = true, .progressive = true},
      .properties = {"low-discrepancy",
                     "(0,m,s)-net in base b for every block of b^m points (none, owen, permute, xor)"},
      .randomization = {RandomizerFamily::base_b_digits, Randomizer::owen},
      .counts = "any n >= 1; nets at n = b^m",
      .params = {},
      .validate = nullptr,
      .count = requested_count,
      .generate = nullptr,  // the registry fills sets from bind
      .bind = bind_faure,
      .seeded = seeded_faure,
  });

  return list;
}

}  // namespace stratum::registry_families
