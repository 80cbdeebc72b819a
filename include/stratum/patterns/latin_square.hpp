#pragma once
/// Random Latin squares as 3D point sets. A Latin square of order m is an
/// m × m array of m symbols, each once in every row and every column (the
/// block design of lecture §7). Its m² cells (row, column, symbol) form an
/// orthogonal array of strength 2: every pair of the three factors takes
/// each of its m² value pairs exactly once. Point r·m + c of the set is
/// ((r + u)/m, (c + v)/m, (L(r, c) + w)/m) with u, v, w uniform: every 2D
/// projection of the n = m² points is a jittered m × m grid (one point per
/// cell), whereas a full 3D jittered grid would need m³ points. This is
/// orthogonal-array sampling (Owen 1992, "Orthogonal arrays for computer
/// experiments, integration and visualization").
///
/// Two ways to draw the square:
/// - Jacobson–Matthews (Jacobson, Matthews 1996, "Generating uniformly
///   distributed random Latin squares"): a Markov chain on Latin squares and
///   "improper" squares (one −1 entry in the 0/1 incidence cube) whose
///   stationary law on the proper ones is uniform. It starts from the cyclic
///   square and makes `steps` moves from proper squares, each followed by
///   the improper excursion it may start (about m moves on average), so it
///   ends on a proper square. No mixing-time bound is known; the default,
///   m² proper moves (about m³ moves in all, the usual budget), is well past
///   the point where the mean number of intercalates (2 × 2 subsquares)
///   stops changing, about m²/4 proper moves for m = 8 to 32.
/// - Permuted cyclic: L(r, c) = τ((ρ(r) + γ(c)) mod m) with uniformly random
///   permutations ρ, γ, τ. Fast for any order, but uniform only over the
///   isotopes of the cyclic group table, not over all Latin squares.
/// Either way the symbol of a given cell is uniform over the m symbols, so
/// every point is uniform in [0, 1)³ and estimates are unbiased.
///
/// Every draw is counter-based (seed, step), so the square depends only on
/// (m, seed, method, steps). The caller supplies the scratch memory.
#include <cstdint>

#include "stratum/patterns/strata.hpp"

namespace stratum {

class LatinSquare {
 public:
  enum class Method { jacobson_matthews, permuted_cyclic };

  /// Largest order: symbols and table entries are 32-bit.
  static constexpr std::uint64_t max_order = 65535;
  /// The default number of moves from proper squares, m².
  static constexpr std::uint64_t default_steps(std::uint64_t order) noexcept { return order * order; }

  LatinSquare(std::uint64_t order, std::uint64_t seed, Method method = Method::jacobson_matthews,
              std::uint64_t steps = ~std::uint64_t{0})
      : order_(order), seed_(seed), method_(method), steps_(steps == ~std::uint64_t{0} ? default_steps(order) : steps) {
    require(order >= 1 && order <= max_order, "m", order, "a Latin square's order must be in [1, 65535]");
  }

  std::uint64_t order() const noexcept { return order_; }
  std::uint64_t count() const noexcept { return order_ * order_; }
  Method method() const noexcept { return method_; }
  std::uint64_t steps() const noexcept { return steps_; }
  /// 32-bit integers of scratch that fill_symbols needs.
  std::uint64_t scratch_size() const noexcept {
    return method_ == Method::jacobson_matthews ? 6 * order_ * order_ : 3 * order_;
  }

  /// Writes the square, symbols[r·m + c] = L(r, c), using scratch_size()
  /// integers of scratch.
  void fill_symbols(std::uint32_t* symbols, std::uint32_t* scratch) const noexcept {
    const std::uint64_t m = order_;
    if (m == 1) {
      symbols[0] = 0;
      return;
    }
    if (method_ == Method::permuted_cyclic) {
      std::uint32_t* rho = scratch;
      std::uint32_t* gamma = scratch + m;
      std::uint32_t* tau = scratch + 2 * m;
      random_permutation(rho, m, hash64(seed_, 0x524f57ULL));
      random_permutation(gamma, m, hash64(seed_, 0x434f4cULL));
      random_permutation(tau, m, hash64(seed_, 0x53594dULL));
      for (std::uint64_t r = 0; r < m; ++r)
        for (std::uint64_t c = 0; c < m; ++c) symbols[r * m + c] = tau[(rho[r] + gamma[c]) % m];
      return;
    }
    JacobsonMatthews chain(m, scratch);
    const std::uint64_t key = hash64(seed_, 0x4a4d4348ULL);
    // Count moves from proper squares only and stop at a proper square: the
    // result is then the steps-th state of the chain watched on proper
    // squares, whose stationary law is uniform. Stopping at the first proper
    // square after a fixed number of all moves would weight each square by
    // the length of the improper excursions leading to it.
    std::uint64_t proper_moves = 0;
    for (std::uint64_t step = 0; proper_moves < steps_ || chain.improper; ++step) {
      if (!chain.improper) ++proper_moves;
      chain.move(key, step);
    }
    for (std::uint64_t r = 0; r < m; ++r)
      for (std::uint64_t c = 0; c < m; ++c) symbols[r * m + c] = chain.rc[2 * (r * m + c)];
  }

  /// Coordinate dim (0: row, 1: column, 2: symbol) of point index = r·m + c,
  /// given its symbol L(r, c).
  template <class Real = double>
  Real coordinate(std::uint64_t index, unsigned dim, std::uint32_t symbol) const noexcept {
    return coordinate_from<Real>(jitter_key(), index, dim, symbol);
  }
  /// The jitter chain (strata.hpp) of the square's points.
  std::uint64_t jitter_key() const noexcept { return jitter_chain(seed_, 0x4c534a4954ULL); }
  /// coordinate(index, dim, symbol) from jitter_key(); rows and columns (dim
  /// 0, 1) need no symbol: each 2D projection of those is a jittered grid.
  template <class Real = double>
  Real coordinate_from(std::uint64_t jitter_key, std::uint64_t index, unsigned dim,
                       std::uint32_t symbol) const noexcept {
    const std::uint64_t cell = dim == 0 ? index / order_ : dim == 1 ? index % order_ : symbol;
    return jittered_cell<Real>(cell, jitter_key, index, dim, order_);
  }

 private:
  /// The incidence cube f(r, c, s) ∈ {−1, 0, 1} stored by its lines: for each
  /// (row, column), (row, symbol) and (column, symbol) pair, the (at most two)
  /// positions of +1 entries along the third axis; `empty` marks a free slot.
  /// A proper square has one +1 per line; an improper one has a single −1
  /// entry whose three lines hold two +1 entries each.
  struct JacobsonMatthews {
    static constexpr std::uint32_t empty = 0xffffffffu;
    std::uint64_t m;
    std::uint32_t* rc;  ///< (r, c) → symbols
    std::uint32_t* rs;  ///< (r, s) → columns
    std::uint32_t* cs;  ///< (c, s) → rows
    bool improper = false;
    std::uint32_t bad_r = 0, bad_c = 0, bad_s = 0;

    JacobsonMatthews(std::uint64_t order, std::uint32_t* scratch)
        : m(order), rc(scratch), rs(scratch + 2 * order * order), cs(scratch + 4 * order * order) {
      for (std::uint64_t k = 0; k < 6 * m * m; ++k) scratch[k] = empty;
      for (std::uint64_t r = 0; r < m; ++r)
        for (std::uint64_t c = 0; c < m; ++c) add(r, c, (r + c) % m);
    }
    static bool holds(const std::uint32_t* line, std::uint64_t v) noexcept { return line[0] == v || line[1] == v; }
    static void insert(std::uint32_t* line, std::uint64_t v) noexcept {
      line[line[0] == empty ? 0 : 1] = static_cast<std::uint32_t>(v);
    }
    static void erase(std::uint32_t* line, std::uint64_t v) noexcept {
      if (line[0] == v) {
        line[0] = line[1];
        line[1] = empty;
      } else {
        line[1] = empty;
      }
    }
    std::uint32_t* rc_line(std::uint64_t r, std::uint64_t c) const noexcept { return rc + 2 * (r * m + c); }
    std::uint32_t* rs_line(std::uint64_t r, std::uint64_t s) const noexcept { return rs + 2 * (r * m + s); }
    std::uint32_t* cs_line(std::uint64_t c, std::uint64_t s) const noexcept { return cs + 2 * (c * m + s); }
    bool is_bad(std::uint64_t r, std::uint64_t c, std::uint64_t s) const noexcept {
      return improper && r == bad_r && c == bad_c && s == bad_s;
    }
    void add(std::uint64_t r, std::uint64_t c, std::uint64_t s) noexcept {
      insert(rc_line(r, c), s);
      insert(rs_line(r, s), c);
      insert(cs_line(c, s), r);
    }
    /// f(r, c, s) += 1 on an entry that is 0 or −1.
    void increment(std::uint64_t r, std::uint64_t c, std::uint64_t s) noexcept {
      if (is_bad(r, c, s)) improper = false;
      else add(r, c, s);
    }
    /// f(r, c, s) −= 1 on an entry that is 1 or (while proper) 0.
    void decrement(std::uint64_t r, std::uint64_t c, std::uint64_t s) noexcept {
      if (holds(rc_line(r, c), s)) {
        erase(rc_line(r, c), s);
        erase(rs_line(r, s), c);
        erase(cs_line(c, s), r);
      } else {
        improper = true;
        bad_r = static_cast<std::uint32_t>(r);
        bad_c = static_cast<std::uint32_t>(c);
        bad_s = static_cast<std::uint32_t>(s);
      }
    }
    /// One move. From a proper square: pick a 0 entry (r, c, s) uniformly;
    /// from an improper one: the −1 entry. Then pick r', c', s' with
    /// f(r', c, s) = f(r, c', s) = f(r, c, s') = 1 (uniformly among the two
    /// choices each when improper) and add +1 at (r,c,s), (r',c',s),
    /// (r',c,s'), (r,c',s') and −1 at (r',c,s), (r,c',s), (r,c,s'),
    /// (r',c',s'). Decrements of the +1 entries come first, so no line ever
    /// holds more than two +1 entries, and (r',c',s') last, so at most one
    /// −1 exists at a time.
    void move(std::uint64_t key, std::uint64_t step) noexcept {
      std::uint64_t r, c, s;
      unsigned pick_r = 0, pick_c = 0, pick_s = 0;
      if (!improper) {
        r = uniform_below(m, key, step, 0);
        c = uniform_below(m, key, step, 1);
        const std::uint64_t present = rc_line(r, c)[0];
        s = uniform_below(m - 1, key, step, 2);
        if (s >= present) ++s;
      } else {
        r = bad_r;
        c = bad_c;
        s = bad_s;
        const std::uint64_t bits = hash64(key, step, 3);
        pick_r = bits & 1u;
        pick_c = (bits >> 1) & 1u;
        pick_s = (bits >> 2) & 1u;
      }
      const std::uint64_t r2 = cs_line(c, s)[pick_r];
      const std::uint64_t c2 = rs_line(r, s)[pick_c];
      const std::uint64_t s2 = rc_line(r, c)[pick_s];
      decrement(r2, c, s);
      decrement(r, c2, s);
      decrement(r, c, s2);
      increment(r, c, s);
      increment(r2, c2, s);
      increment(r2, c, s2);
      increment(r, c2, s2);
      decrement(r2, c2, s2);
    }
  };

  std::uint64_t order_;
  std::uint64_t seed_;
  Method method_;
  std::uint64_t steps_;
};

}  // namespace stratum
