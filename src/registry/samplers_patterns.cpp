/// Registry entries of the finite patterns.
#include <algorithm>
#include <bit>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "bulk_permutation.hpp"
#include "families.hpp"
#include "stratum/patterns/grid.hpp"
#include "stratum/patterns/jittered.hpp"
#include "stratum/patterns/keyed_pairs.hpp"
#include "stratum/patterns/latin_hypercube.hpp"
#include "stratum/patterns/latin_square.hpp"
#include "stratum/patterns/multi_jittered.hpp"
#include "stratum/patterns/n_queens.hpp"
#include "stratum/patterns/random.hpp"
#include "stratum/patterns/zaremba.hpp"
#include "stratum/randomizers/cranley_patterson.hpp"
#include "support.hpp"

namespace stratum::registry_families {

using namespace registry_support;

/// strata= as counts per dimension ("4x8" → {4, 8}).
static std::vector<std::uint64_t> strata_param(const SamplerRequest& request) {
  const auto& parts = request.values.integers("strata");
  return {parts.begin(), parts.end()};
}

/// The strata of a grid or jittered request: strata= if given, else k^d = n.
static StrataShape strata_of(const SamplerRequest& request) {
  const std::uint64_t n = *request.n;
  if (const auto text = param_text(request, "strata")) {
    auto parts = strata_param(request);
    require(parts.size() == request.d, "strata", *text,
            "needs one count per dimension (d = " + std::to_string(request.d) + ")");
    StrataShape shape(std::move(parts));
    require(shape.count() == n, "n", n, "must equal the product of strata=" + *text);
    return shape;
  }
  return StrataShape::equal(n, request.d);
}

static std::uint64_t nearest_square_below(std::uint64_t n) { return integer_root(n, 2); }

/// Order m of a latin-square request (n = m^2), or a message naming n.
static std::uint64_t latin_square_order(const SamplerRequest& request) {
  const std::uint64_t n = *request.n;
  const std::uint64_t m = nearest_square_below(n);
  if (m * m != n)
    throw invalid_argument("n", std::to_string(n),
                           "latin-square takes n = m^2 points (order m Latin square; nearest: " +
                               std::to_string(m * m) + ", " + std::to_string((m + 1) * (m + 1)) + ")");
  require(m <= LatinSquare::max_order, "n", n, "the order m = sqrt(n) must be at most 65535");
  return m;
}

static LatinSquare latin_square_of(const SamplerRequest& request) {
  const std::uint64_t m = latin_square_order(request);
  const LatinSquare::Method kind = request.values.text("method") == "permuted-cyclic"
                                       ? LatinSquare::Method::permuted_cyclic
                                       : LatinSquare::Method::jacobson_matthews;
  const std::uint64_t steps = request.values.has("steps") ? static_cast<std::uint64_t>(request.values.integer("steps"))
                                                          : LatinSquare::default_steps(m);
  // Each move from a proper square costs about m moves with its improper
  // excursion: bound the total near 2^28 moves (seconds).
  constexpr std::uint64_t max_moves = std::uint64_t{1} << 28;
  // The message is built only when the limit is exceeded: a renderer makes a square per pixel and dimension.
  if (kind == LatinSquare::Method::jacobson_matthews && steps > max_moves / m)
    throw invalid_argument("steps", to_message_string(steps),
                           "Jacobson-Matthews takes at most 2^28 / m = " + std::to_string(max_moves / m) +
                               " proper moves here (m = " + std::to_string(m) +
                               ", default m^2); use method=permuted-cyclic or a smaller steps= for large squares");
  return LatinSquare(m, request.seed, kind, steps);
}

static double aspect_of(const SamplerRequest& request) { return request.values.real("aspect"); }

static MultiJittered multi_jittered_of(const SamplerRequest& request) {
  const std::uint64_t n = *request.n;
  if (const auto text = param_text(request, "strata")) {
    const auto parts = strata_param(request);
    require(parts.size() == 2, "strata", *text, "multi-jittered needs columns x rows, e.g. strata=4x8");
    require(n % parts[0] == 0 && n / parts[0] == parts[1], "n", n, "must equal the product of strata=" + *text);
    return MultiJittered(parts[0], parts[1], request.seed);
  }
  return MultiJittered::closest_to_square(n, request.seed);
}

static NQueens::Method n_queens_method(const SamplerRequest& request) {
  return request.values.text("method") == "formula" ? NQueens::Method::formula : NQueens::Method::random;
}

/// Dimensions in blocks of 8: their permutations (32-bit cells when n fits),
/// then the rows, so the writes are whole cache lines and each row's hash
/// is shared by the block's coordinates (the points of LatinHypercube::generate).
template <class Index>
static void fill_latin_hypercube(const LatinHypercube& lhs, const SamplerRequest& request, double* out) {
  constexpr unsigned block = 8;
  const std::uint64_t n = *request.n;
  const unsigned d = request.d;
  std::vector<Index> cells(std::size_t{std::min(block, d)} * n);
  for (unsigned first = 0; first < d; first += block) {
    const unsigned width = std::min(block, d - first);
    for (unsigned b = 0; b < width; ++b) {
      Index* column = cells.data() + std::size_t{b} * n;
      if constexpr (sizeof(Index) == sizeof(std::uint32_t))
        bulk_random_permutation(column, n, lhs.permutation_key(first + b));
      else lhs.permutation(first + b, column);
    }
    parallel_rows(n, request.threads, [&](std::uint64_t begin, std::uint64_t end) {
      for (std::uint64_t i = begin; i < end; ++i) {
        const std::uint64_t key = lhs.row_key(i);
        double* row = out + i * d + first;
        for (unsigned b = 0; b < width; ++b)
          row[b] = lhs.coordinate_in_row(cells[std::size_t{b} * n + i], key, first + b);
      }
    });
  }
}

static PointSet generate_latin_hypercube(const SamplerRequest& request) {
  const LatinHypercube lhs(*request.n, request.d, request.seed, request.values.flag("centered"));
  PointSet points = allocate_points(*request.n, request.d);
  if (*request.n <= (std::uint64_t{1} << 32)) fill_latin_hypercube<std::uint32_t>(lhs, request, points.data.get());
  else fill_latin_hypercube<std::uint64_t>(lhs, request, points.data.get());
  return points;
}

/// A SeededGenerator whose points() calls Derived::point directly, its
/// body inlined in the loop: a shadow-ray array in one call.
template <class Derived>
class InlinePoints : public SeededGenerator {
 public:
  void points(const std::uint64_t* state, std::uint64_t first, std::uint64_t count, unsigned coordinates,
              double* out) const noexcept final {
    const Derived& self = static_cast<const Derived&>(*this);
    for (std::uint64_t k = 0; k < count; ++k) self.Derived::point(state, first + k, coordinates, out + k * coordinates);
  }
};

/// N-rooks as a SeededGenerator: a seed's state is its permutations, one
/// word per cell (coordinate j's n cells from word 1 + j·n), after the
/// jitter chain's shared link (word 0), so a set's points need no
/// allocation: the renderer's sets of a few points per pixel and dimension.
/// The points of generate_latin_hypercube (tested).
class LatinHypercubeSeeded final : public InlinePoints<LatinHypercubeSeeded> {
 public:
  explicit LatinHypercubeSeeded(const SamplerRequest& request)
      : shape_(*request.n, request.d, 0, request.values.flag("centered")) {}
  std::size_t state_words() const noexcept override { return 1 + shape_.count() * shape_.dimensions(); }
  void seed(std::uint64_t seed, unsigned coordinates, std::uint64_t* state) const noexcept override {
    const LatinHypercube lhs(shape_.count(), shape_.dimensions(), seed, shape_.centered());
    state[0] = lhs.jitter_key();
    for (unsigned j = 0; j < coordinates; ++j) lhs.permutation(j, state + 1 + j * shape_.count());
  }
  void point(const std::uint64_t* state, std::uint64_t index, unsigned coordinates,
             double* out) const noexcept override {
    const std::uint64_t row = LatinHypercube::row_key_of(state[0], index);
    for (unsigned j = 0; j < coordinates; ++j)
      out[j] = shape_.coordinate_in_row(state[1 + j * shape_.count() + index], row, j);
  }

 private:
  LatinHypercube shape_;  ///< n, d and centered (its seed unused: coordinate_in_row reads none)
};

/// Multi-jittered as a SeededGenerator: a seed's state is each point's fine
/// column (words 1 … n) and fine row (words n + 1 … 2n) after the jitter
/// chain's shared link (word 0), the shuffles' scratch last; the points of
/// the entry's generate (tested), without a set's allocation.
class MultiJitteredSeeded final : public InlinePoints<MultiJitteredSeeded> {
 public:
  explicit MultiJitteredSeeded(const MultiJittered& shape) : shape_(shape) {}
  std::size_t state_words() const noexcept override { return 1 + 2 * shape_.count() + shape_.scratch_size(); }
  void seed(std::uint64_t seed, unsigned coordinates, std::uint64_t* state) const noexcept override {
    const MultiJittered mj(shape_.columns(), shape_.rows(), seed);
    const std::uint64_t n = mj.count();
    std::uint64_t* scratch = state + 1 + 2 * n;
    state[0] = mj.jitter_key();
    for (std::uint64_t i = 0; i < mj.columns(); ++i)
      mj.column_cells(i, scratch, [&](std::uint64_t index, std::uint64_t cell) { state[1 + index] = cell; });
    if (coordinates < 2) return;
    for (std::uint64_t j = 0; j < mj.rows(); ++j)
      mj.row_cells(j, scratch, [&](std::uint64_t index, std::uint64_t cell) { state[1 + n + index] = cell; });
  }
  void point(const std::uint64_t* state, std::uint64_t index, unsigned coordinates,
             double* out) const noexcept override {
    for (unsigned j = 0; j < coordinates; ++j)
      out[j] = jittered_cell(state[1 + j * shape_.count() + index], state[0], index, j, shape_.count());
  }

 private:
  MultiJittered shape_;  ///< columns and rows (its seed unused)
};

/// A Latin square as a SeededGenerator: a seed's state is the jitter
/// chain's shared link (word 0) and, where the symbol coordinate is asked,
/// the square's symbols (words 1 … n; made with the chain's scratch, the
/// one allocation of a seed, and only there). Rows and columns need no
/// square, so the renderer's 2D sets (the first two coordinates) run no
/// Jacobson–Matthews chain.
/// The points of the entry's generate (tested).
class LatinSquareSeeded final : public InlinePoints<LatinSquareSeeded> {
 public:
  explicit LatinSquareSeeded(const LatinSquare& shape) : shape_(shape) {}
  std::size_t state_words() const noexcept override { return 1 + shape_.count(); }
  void seed(std::uint64_t seed, unsigned coordinates, std::uint64_t* state) const noexcept override {
    const LatinSquare square(shape_.order(), seed, shape_.method(), shape_.steps());
    state[0] = square.jitter_key();
    if (coordinates < 3) return;
    std::vector<std::uint32_t> symbols(square.count()), scratch(square.scratch_size());  // the request's memory
    square.fill_symbols(symbols.data(), scratch.data());
    std::copy(symbols.begin(), symbols.end(), state + 1);
  }
  void point(const std::uint64_t* state, std::uint64_t index, unsigned coordinates,
             double* out) const noexcept override {
    for (unsigned j = 0; j < coordinates; ++j)
      out[j] = shape_.coordinate_from(state[0], index, j, j == 2 ? static_cast<std::uint32_t>(state[1 + index]) : 0);
  }

 private:
  LatinSquare shape_;  ///< order, method and steps (its seed unused: coordinate_from reads none)
};

/// n-queens as a SeededGenerator: a seed's state is the jitter chain's
/// shared link (word 0), its Cranley–Patterson shifts under cp (words 1, 2)
/// and each point's two cells (x low, y high: n ≤ 2^32) after the solution's
/// symmetry, so a renderer's set is one search and no generator bound per
/// set. The points of its generator (tested).
class NQueensSeeded final : public InlinePoints<NQueensSeeded> {
 public:
  NQueensSeeded(std::uint64_t count, NQueens::Method method, bool rotate)
      : count_(count), method_(method), rotate_(rotate) {}
  std::size_t state_words() const noexcept override { return 3 + count_; }
  void seed(std::uint64_t seed, unsigned, std::uint64_t* state) const noexcept override {
    const NQueens queens(count_, seed, method_);  // the request was validated: no throw (its search allocates)
    state[0] = queens.jitter_key();
    if (rotate_) {
      const CranleyPattersonRotation rotation(seed);
      state[1] = std::bit_cast<std::uint64_t>(rotation.shift(0)),
      state[2] = std::bit_cast<std::uint64_t>(rotation.shift(1));
    }
    for (std::uint64_t i = 0; i < count_; ++i) state[3 + i] = queens.cell(i, 0) | queens.cell(i, 1) << 32;
  }
  void point(const std::uint64_t* state, std::uint64_t index, unsigned coordinates,
             double* out) const noexcept override {
    const std::uint64_t cells = state[3 + index];
    for (unsigned j = 0; j < coordinates; ++j) {
      const double value = jittered_cell(j == 0 ? cells & 0xffffffffULL : cells >> 32, state[0], index, j, count_);
      out[j] = rotate_ ? CranleyPattersonRotation::rotate(value, std::bit_cast<double>(state[1 + j])) : value;
    }
  }

 private:
  std::uint64_t count_;
  NQueens::Method method_;
  bool rotate_;
};

/// cmj as a SeededGenerator: the construction (its domains and dividers)
/// built once, a seed's state what a point needs of Kensler's pattern p
/// (CorrelatedMultiJittered::Keys: eight 32-bit words, two per state word);
/// a point's shuffled index serves both coordinates. The points of its
/// generator (tested).
class CmjSeeded final : public SeededGenerator {
  using Keys = CorrelatedMultiJittered::Keys;
  /// A renderer's set draws every point of it, so a small set's seed makes
  /// them all at once (up to this n, its points are the state: the
  /// permutations' walks side by side, and a point drawn is a load) ...
  static constexpr std::uint64_t max_stored = 64;
  /// ... and a larger one's state holds the column and row permutations (a
  /// byte each, up to this many together): m + k permutations a set instead
  /// of two a point. Beyond both, the keys alone.
  static constexpr std::uint64_t max_tabled = 64;
  enum class Form { points, tables, keys };

 public:
  explicit CmjSeeded(const CorrelatedMultiJittered& shape)
      : shape_(shape),
        form_(shape.count() <= max_stored                    ? Form::points
              : shape.columns() + shape.rows() <= max_tabled ? Form::tables
                                                             : Form::keys) {}
  std::size_t state_words() const noexcept override {
    if (form_ == Form::points) return 2 * shape_.count();
    return 4 + (form_ == Form::tables ? (shape_.columns() + shape_.rows() + 7) / 8 : 0);
  }
  void seed(std::uint64_t seed, unsigned coordinates, std::uint64_t* state) const noexcept override {
    const Keys k = shape_.keys(CorrelatedMultiJittered::pattern_of(seed));
    if (form_ == Form::keys) return store_keys(k, state);
    const auto m = static_cast<std::uint32_t>(shape_.columns()), rows = static_cast<std::uint32_t>(shape_.rows());
    std::uint8_t table[2 * max_stored + 8] = {};  // m + k ≤ 2n (points) or ≤ max_tabled (tables)
    fill_last_by_elimination(table, m, [&](std::uint32_t c) { return shape_.permuted_column(k, c); });
    fill_last_by_elimination(table + m, rows, [&](std::uint32_t r) { return shape_.permuted_row(k, r); });
    if (form_ == Form::tables) {
      store_keys(k, state);
      std::memcpy(state + 4, table, 8 * (state_words() - 4));
      return;
    }
    const auto n = static_cast<std::uint32_t>(shape_.count());
    std::uint8_t shuffled[max_stored];
    fill_last_by_elimination(shuffled, n, [&](std::uint32_t i) { return shape_.shuffled(k, i); });
    for (std::uint32_t i = 0; i < n; ++i) {
      double point[2] = {0.0, 0.0};
      shape_.sample_of_shuffled(k, table, table + m, shuffled[i], std::min(coordinates, 2u), point);
      state[2 * i] = std::bit_cast<std::uint64_t>(point[0]), state[2 * i + 1] = std::bit_cast<std::uint64_t>(point[1]);
    }
  }
  void point(const std::uint64_t* state, std::uint64_t index, unsigned coordinates,
             double* out) const noexcept override {
    points(state, index, 1, coordinates, out);
  }
  void points(const std::uint64_t* state, std::uint64_t first, std::uint64_t count, unsigned coordinates,
              double* out) const noexcept override {  // inline per point: a shadow-ray array in one call
    if (form_ == Form::points) {
      for (std::uint64_t i = 0; i < count; ++i)
        for (unsigned j = 0; j < coordinates; ++j)
          out[i * coordinates + j] = std::bit_cast<double>(state[2 * (first + i) + j]);
      return;
    }
    const Keys k = keys_of(state);
    if (form_ == Form::tables) {
      const auto* columns = reinterpret_cast<const std::uint8_t*>(state + 4);  // bytes of the words: allowed aliasing
      const std::uint8_t* rows = columns + shape_.columns();
      for (std::uint64_t i = 0; i < count; ++i)
        shape_.sample_of_shuffled(k, columns, rows, shape_.shuffled(k, first + i), coordinates, out + i * coordinates);
      return;
    }
    for (std::uint64_t i = 0; i < count; ++i) shape_.sample_for(k, first + i, coordinates, out + i * coordinates);
  }

 private:
  /// out[i] = permuted(i) for i < l − 1, and the last value the one the
  /// others leave (the XOR of 0 … l − 1 and of the values before it): a
  /// permutation's walk saved.
  template <class Entry, class Permuted>
  static void fill_last_by_elimination(Entry* out, std::uint32_t l, Permuted permuted) noexcept {
    std::uint32_t left = l - 1;
    for (std::uint32_t i = 0; i + 1 < l; ++i) out[i] = static_cast<Entry>(permuted(i)), left ^= i ^ out[i];
    out[l - 1] = static_cast<Entry>(left);
  }
  static void store_keys(const Keys& k, std::uint64_t* state) noexcept {
    const auto pair = [](std::uint32_t low, std::uint32_t high) { return low | std::uint64_t{high} << 32; };
    state[0] = pair(k.shuffle, k.across), state[1] = pair(k.down, k.jitter_x);
    state[2] = pair(k.jitter_y, k.shuffle_rotation), state[3] = pair(k.across_rotation, k.down_rotation);
  }
  static Keys keys_of(const std::uint64_t* state) noexcept {
    const auto low = [](std::uint64_t word) { return static_cast<std::uint32_t>(word); };
    const auto high = [](std::uint64_t word) { return static_cast<std::uint32_t>(word >> 32); };
    return {low(state[0]), high(state[0]), low(state[1]), high(state[1]),
            low(state[2]), high(state[2]), low(state[3]), high(state[3])};
  }
  CorrelatedMultiJittered shape_;  ///< n, aspect (its own pattern unused)
  Form form_;
};

static SamplerInfo latin_hypercube_entry(std::string name, std::string description) {
  return {
      .name = std::move(name),
      .kind = "pattern",
      .description = std::move(description),
      .min_dim = 1,
      .max_dim = 1u << 16,
      .flags = {.self_randomized = true},
      .properties = {"Latin (one point per 1/n interval in every coordinate)", "unbiased"},
      .randomization = {RandomizerFamily::seeded, Randomizer::none},
      .counts = "any n >= 1",
      .params = {params::flag("centered", "1: points at the interval centres (scipy's scramble=False)", "0")},
      .validate = nullptr,
      .count = requested_count,
      .generate = generate_latin_hypercube,
      .seeded = [](const SamplerRequest& request) -> std::shared_ptr<const SeededGenerator> {
        return std::make_shared<const LatinHypercubeSeeded>(request);
      },
  };
}

/// The index-addressable patterns' constructions, for generate_rotated and bind_rotated.
static RandomPattern random_pattern(const SamplerRequest& request) { return RandomPattern(request.seed); }
static Grid grid_pattern(const SamplerRequest& request) { return Grid(strata_of(request)); }
static Jittered jittered_pattern(const SamplerRequest& request) { return Jittered(strata_of(request), request.seed); }
static CorrelatedMultiJittered cmj_pattern(const SamplerRequest& request) {
  return CorrelatedMultiJittered(*request.n, request.seed, aspect_of(request));
}
static NQueens n_queens_pattern(const SamplerRequest& request) {
  return NQueens(*request.n, request.seed, n_queens_method(request));
}
static Zaremba zaremba_pattern(const SamplerRequest& request) { return Zaremba(*request.n); }

std::vector<SamplerInfo> patterns() {
  std::vector<SamplerInfo> list;

  list.push_back({
      .name = "random",
      .kind = "pattern",
      .description = "independent uniform points from a counter-based generator; point i depends only on (seed, i), "
                     "so start=K continues a run",
      .min_dim = 1,
      .max_dim = 1u << 16,
      .flags = {.index_addressable = true, .progressive = true, .self_randomized = true, .prefix_unbiased = {"none"}},
      .properties = {"unstratified"},
      .randomization = {RandomizerFamily::seeded, Randomizer::none},
      .counts = "any n >= 1",
      .params = {},
      .validate = nullptr,
      .count = requested_count,
      .generate = generate_rotated(random_pattern),
      .bind = bind_rotated(random_pattern),
      .keyed_pairs = keyed_under<RandomPairs>(Randomizer::none),
  });

  const Param strata_schema =
      params::integers("strata", "strata per dimension, e.g. 4x8 (product must equal n)", "", at_least(1), {}, 'x');
  const std::string strata_counts = "n = k^d (a perfect d-th power), or any n with strata=n1x...xnd of product n";

  list.push_back({
      .name = "grid",
      .kind = "pattern",
      .description = "cell centres of an n1 x ... x nd grid (the midpoint product rule)",
      .min_dim = 1,
      .max_dim = 1u << 16,
      .flags = {.index_addressable = true},
      .properties = {"stratified (one point per cell)", "deterministic"},
      .randomization = {RandomizerFamily::rotation, Randomizer::none},
      .counts = strata_counts,
      .params = {strata_schema},
      .validate = [](const SamplerRequest& request) { strata_of(request); },
      .count = requested_count,
      .generate = generate_rotated(grid_pattern),
      .bind = bind_rotated(grid_pattern),
      .seeded = seeded_rotated(grid_pattern),
  });

  list.push_back({
      .name = "jittered",
      .kind = "pattern",
      .description = "one uniform point in each cell of an n1 x ... x nd grid (Cook 1986, stratified sampling)",
      .min_dim = 1,
      .max_dim = 1u << 16,
      .flags = {.index_addressable = true, .self_randomized = true},
      .properties = {"stratified (one point per cell)", "unbiased"},
      .randomization = {RandomizerFamily::seeded, Randomizer::none},
      .counts = strata_counts,
      .params = {strata_schema},
      .validate = [](const SamplerRequest& request) { strata_of(request); },
      .count = requested_count,
      .generate = generate_rotated(jittered_pattern),
      .bind = bind_rotated(jittered_pattern),
      .keyed_pairs = keyed_under<JitteredPairs>(Randomizer::none),
  });

  list.push_back(latin_hypercube_entry(
      "n-rooks",
      "N-rooks / Latin hypercube: one random permutation per dimension (McKay, Beckman, Conover 1979; Shirley 1991)"));
  list.push_back(latin_hypercube_entry(
      "latin-hypercube",
      "alias of n-rooks (same points for the same request): Latin hypercube sampling (McKay et al. 1979)"));

  list.push_back({
      .name = "multi-jittered",
      .kind = "pattern",
      .description = "multi-jittered: m x k strata and Latin in x and y (Chiu, Shirley, Wang 1994)",
      .min_dim = 2,
      .max_dim = 2,
      .flags = {.self_randomized = true},
      .properties = {"Latin in x and y", "one point per m x k stratum", "unbiased"},
      .randomization = {RandomizerFamily::seeded, Randomizer::none},
      .counts = "any n >= 1 (m x k with m <= k closest to sqrt(n); m = 1 for prime n), or strata=mxk of product n",
      .params = {params::integers("strata",
                                  "columns x rows, e.g. 4x8 (product must equal n); default: closest to "
                                  "square",
                                  "", at_least(1), {2, 2}, 'x')},
      .validate = [](const SamplerRequest& request) { multi_jittered_of(request); },
      .count = requested_count,
      .generate =
          [](const SamplerRequest& request) {
            const MultiJittered mj = multi_jittered_of(request);
            PointSet points = allocate_points(*request.n, 2);
            double* out = points.data.get();
            parallel_rows(mj.columns(), request.threads, [&](std::uint64_t begin, std::uint64_t end) {
              std::vector<std::uint64_t> scratch(mj.rows());
              for (std::uint64_t i = begin; i < end; ++i) mj.fill_x(i, out, scratch.data());
            });
            parallel_rows(mj.rows(), request.threads, [&](std::uint64_t begin, std::uint64_t end) {
              std::vector<std::uint64_t> scratch(mj.columns());
              for (std::uint64_t j = begin; j < end; ++j) mj.fill_y(j, out, scratch.data());
            });
            return points;
          },
      .seeded = [](const SamplerRequest& request) -> std::shared_ptr<const SeededGenerator> {
        return std::make_shared<const MultiJitteredSeeded>(multi_jittered_of(request));
      },
  });

  list.push_back({
      .name = "cmj",
      .kind = "pattern",
      .description = "correlated multi-jittered, index-addressable with hashed permutations (Kensler 2013)",
      .min_dim = 2,
      .max_dim = 2,
      .flags = {.index_addressable = true, .self_randomized = true},
      .properties = {"Latin in y",
                     "Latin in x and one point per m x k stratum when n = m*k (m = floor(sqrt(n*aspect)))", "unbiased"},
      .randomization = {RandomizerFamily::seeded, Randomizer::none},
      .counts = "any n in [1, 2^32 - 1]; fully stratified when n = m * ceil(n/m), e.g. squares and m(m+1)",
      .params = {params::real("aspect", "columns / rows of the strata (Kensler's a)", "1", above(0))},
      .validate = [](const SamplerRequest& request) { CorrelatedMultiJittered(*request.n, 0, aspect_of(request)); },
      .count = requested_count,
      .generate = generate_rotated(cmj_pattern),
      .bind = bind_rotated(cmj_pattern),
      .seeded = [](const SamplerRequest& request) -> std::shared_ptr<const SeededGenerator> {
        if (request.randomizer != Randomizer::none) return nullptr;
        return std::make_shared<const CmjSeeded>(cmj_pattern(request));
      },
  });

  list.push_back({
      .name = "n-queens",
      .kind = "pattern",
      .description = "N-queens: one point per row and column of an n x n grid, no two cells on a diagonal; a random "
                     "solution by conflict-reducing swaps from a random permutation (Sosic, Gu 1990), or explicit "
                     "solutions with method=formula (a*i+b mod n when gcd(n,6)=1, else Hoffman-Loessi-Moore 1969); "
                     "a random symmetry of the square, jittered in the cells; by default Cranley-Patterson "
                     "rotated (unbiased: the random solutions' cell occupancy is not exactly uniform), none keeps "
                     "the cells on the fixed n x n grid",
      .min_dim = 2,
      .max_dim = 2,
      .flags = {.self_randomized = true},
      .properties = {"Latin in x and y (on the rotated grid under cp)",
                     "no two points in a diagonal of cells (none; cp: of the rotated, wrapped grid)",
                     "unbiased with cp, the default (none: only method=formula with gcd(n,6)=1)"},
      .randomization = {RandomizerFamily::rotation, Randomizer::cp},
      .counts = "n = 1 or n >= 4 (no n-queens solution exists for n = 2, 3); method=random: n <= 2^24",
      .params = {params::choice("method",
                                "random (local search, well spread) or formula (explicit solutions on a few lines)",
                                "random", {"random", "formula"})},
      .validate = [](const SamplerRequest& request) { NQueens::check(*request.n, n_queens_method(request)); },
      .count = requested_count,
      .generate = generate_rotated(n_queens_pattern),
      .bind = bind_rotated(n_queens_pattern),
      .seeded = [](const SamplerRequest& request) -> std::shared_ptr<const SeededGenerator> {
        return std::make_shared<const NQueensSeeded>(*request.n, n_queens_method(request),
                                                     request.randomizer == Randomizer::cp);
      },
  });

  list.push_back({
      .name = "latin-square",
      .kind = "pattern",
      .description = "random Latin square of order m as n = m^2 points (row, column, symbol) in [0,1)^3, jittered "
                     "in their cells: every 2D projection is an m x m jittered grid (Jacobson-Matthews 1996 for "
                     "uniform squares, or a permuted cyclic square)",
      .min_dim = 3,
      .max_dim = 3,
      .flags = {.self_randomized = true},
      .properties = {"orthogonal array of strength 2 (each 2D projection one point per m x m cell)",
                     "Latin square (each symbol once per row and column)", "unbiased"},
      .randomization = {RandomizerFamily::seeded, Randomizer::none},
      .counts =
          "n = m^2 (m <= 65535; jacobson-matthews by default needs m^3 <= 2^28, i.e. m <= 645; steps= can lower it)",
      .params = {params::choice("method",
                                "jacobson-matthews (uniform, MCMC) or permuted-cyclic (isotopes of Z_m, fast)",
                                "jacobson-matthews", {"jacobson-matthews", "permuted-cyclic"}),
                 params::integer("steps",
                                 "Jacobson-Matthews moves from proper squares (default m^2, about m^3 moves "
                                 "in all)",
                                 "", at_least(0))},
      .validate = [](const SamplerRequest& request) { latin_square_of(request); },
      .count = requested_count,
      .generate =
          [](const SamplerRequest& request) {
            const LatinSquare square = latin_square_of(request);
            std::vector<std::uint32_t> symbols(square.count());
            std::vector<std::uint32_t> scratch(square.scratch_size());
            square.fill_symbols(symbols.data(), scratch.data());
            const std::uint64_t key = square.jitter_key();
            return fill_index_addressable(*request.n, 3, request.threads, [&](std::uint64_t i, unsigned j) {
              return square.coordinate_from(key, i, j, symbols[i]);
            });
          },
      .seeded = [](const SamplerRequest& request) -> std::shared_ptr<const SeededGenerator> {
        return std::make_shared<const LatinSquareSeeded>(latin_square_of(request));
      },
  });

  list.push_back({
      .name = "zaremba",
      .kind = "pattern",
      .description = "Zaremba's points: Hammersley (i/N, phi_2(i)) with every second binary digit of i complemented "
                     "(Zaremba 1968; Halton, Zaremba 1969)",
      .min_dim = 2,
      .max_dim = 2,
      .flags = {.index_addressable = true},
      .properties = {"low-discrepancy", "Latin in x", "(0,k,2)-net in base 2 when n = 2^k", "deterministic"},
      .randomization = {RandomizerFamily::rotation, Randomizer::none},
      .counts = "any n >= 1 (Zaremba's set exactly for n = 2^k)",
      .params = {},
      .validate = nullptr,
      .count = requested_count,
      .generate = generate_rotated(zaremba_pattern),
      .bind = bind_rotated(zaremba_pattern),
      .seeded = seeded_rotated(zaremba_pattern),
  });

  return list;
}

}  // namespace stratum::registry_families
