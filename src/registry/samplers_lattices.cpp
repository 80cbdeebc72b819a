/// Registry entries: rank-1 lattices (fibonacci, lattice) and the lattice-like
/// sequences (kronecker, lattice-sequence).
#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include <cmath>
#include <tuple>

#include "families.hpp"
#include "stratum/randomizers/cranley_patterson.hpp"
#include "stratum/sequences/kronecker.hpp"
#include "stratum/sequences/lattice.hpp"
#include "stratum/sequences/lattice_sequence.hpp"
#include "stratum/util/error.hpp"
#include "support.hpp"
#include "stratum/util/interrupt.hpp"

namespace stratum::registry_families {

using namespace registry_support;

namespace {

/// Korobov search limit: n x d point-coordinates per candidate.
constexpr std::uint64_t search_limit = std::uint64_t{1} << 26;

double param_gamma(const SamplerRequest& request) { return request.values.real("gamma"); }

/// Kronecker's offset s (default 0) and α (d reals; absent: R_d), checked by
/// the header's constructor except for the count and the syntax.
Kronecker kronecker_from(const SamplerRequest& request) {
  const double offset = request.values.real("offset");
  if (!request.values.has("alpha"))  // R_d's vector: a root found once per (d, offset)
    return *shared_construction<Kronecker>(std::pair{request.d, offset}, [&] { return Kronecker(request.d, offset); });
  const std::vector<double>& alpha = request.values.reals("alpha");
  require(alpha.size() == request.d, "alpha", *param_text(request, "alpha"),
          "has " + std::to_string(alpha.size()) + " entries; d = " + std::to_string(request.d) + " needs " +
              std::to_string(request.d));
  return Kronecker(alpha, offset);
}

/// The lattice sequence's generating vector: generator= (d positive
/// integers) or the default vector's first d components (d <= 32).
LatticeSequence lattice_sequence_from(const SamplerRequest& request) {
  if (!request.values.has("generator")) {
    require(request.d <= LatticeSequence::default_generator.size(), "d", request.d,
            "the default generating vector has 32 components; give generator= (d integers) for more dimensions");
    return LatticeSequence(request.d);
  }
  const std::vector<std::int64_t>& generator = request.values.integers("generator");
  require(generator.size() == request.d, "generator", *param_text(request, "generator"),
          "has " + std::to_string(generator.size()) + " entries; d = " + std::to_string(request.d) + " needs " +
              std::to_string(request.d));
  return LatticeSequence(std::vector<std::uint64_t>(generator.begin(), generator.end()));
}

/// An index-addressable sequence from `start`, rotated under cp.
std::optional<std::array<std::uint64_t, Rank1Lattice::max_dimensions>> explicit_generator(
    const SamplerRequest& request) {
  const bool generator = request.values.has("generator");
  const bool a = request.values.has("a");
  const std::uint64_t n = *request.n;
  if (generator && a)
    throw invalid_argument("generator", *param_text(request, "generator"), "give generator= or a=, not both");
  if (generator) {
    const std::vector<std::int64_t>& entries = request.values.integers("generator");
    require(entries.size() == request.d, "generator", *param_text(request, "generator"),
            "has " + std::to_string(entries.size()) + " entries; d = " + std::to_string(request.d) + " needs " +
                std::to_string(request.d));
    std::array<std::uint64_t, Rank1Lattice::max_dimensions> z{};
    for (std::size_t j = 0; j < entries.size(); ++j) {
      const std::int64_t value = entries[j];
      require(value >= 1 && static_cast<std::uint64_t>(value) < std::max<std::uint64_t>(n, 2), "generator",
              "entry " + std::to_string(j) + " = " + std::to_string(value),
              "entries must be in [1, n) = [1, " + std::to_string(n) + ")");
      z[j] = static_cast<std::uint64_t>(value);
    }
    return z;
  }
  if (a) return korobov_generator(n, static_cast<std::uint64_t>(request.values.integer("a")), request.d);
  return std::nullopt;
}

/// The best Korobov parameter, candidates scored in parallel (each score
/// depends only on its candidate, so the result is the same on any number
/// of threads).
std::uint64_t search_korobov(std::uint64_t n, unsigned d, double gamma, unsigned threads) {
  const KorobovSearch search(n, d, gamma);
  const std::uint64_t count = search.candidate_count();
  std::vector<std::uint64_t> parameters(count);
  std::vector<double> scores(count);
  for (std::uint64_t t = 0; t < count; ++t) parameters[t] = search.candidate(t);
  const auto score_range = [&](std::uint64_t begin, std::uint64_t end) {
    for (std::uint64_t t = begin; t < end; ++t) {
      check_interrupt();
      scores[t] = search.score(parameters[t]);
    }
  };
  if (threads <= 1 || count == 1) {
    score_range(0, count);
  } else {
    oneapi::tbb::task_arena arena(static_cast<int>(threads));
    arena.execute([&] {
      oneapi::tbb::parallel_for(oneapi::tbb::blocked_range<std::uint64_t>(0, count, 1),
                                [&](const auto& range) { score_range(range.begin(), range.end()); });
    });
  }
  return parameters[KorobovSearch::best_of(scores, parameters)];
}

/// The lattice of a request: z from generator= or a=, else the Korobov
/// search's (its result depends on (n, d, gamma) only: done once per process,
/// not per set or binding).
Rank1Lattice lattice_of(const SamplerRequest& request) {
  const std::uint64_t n = *request.n;
  auto z = explicit_generator(request);
  if (!z) {
    const double gamma = param_gamma(request);
    const auto best = shared_construction<std::uint64_t>(
        std::tuple{n, request.d, gamma}, [&] { return search_korobov(n, request.d, gamma, request.threads); });
    z = korobov_generator(n, *best, request.d);
  }
  return Rank1Lattice(n, std::span<const std::uint64_t>(z->data(), request.d));
}

Rank1Lattice fibonacci_of(const SamplerRequest& request) { return fibonacci_lattice(*request.n); }

std::string nearby_fibonacci(std::uint64_t n) {
  unsigned k = 2;
  while (k < 93 && fibonacci_number(k + 1) < n) ++k;
  return std::to_string(fibonacci_number(k)) + " or " + std::to_string(fibonacci_number(k + 1));
}

}  // namespace

std::vector<SamplerInfo> lattices() {
  std::vector<SamplerInfo> list;

  list.push_back({
      .name = "fibonacci",
      .kind = "pattern",
      .description = "Fibonacci lattice: n = F_k points frac(i (1, F_{k-1}) / n) (Zaremba 1966; Sloan, Joe 1994); "
                     "for other n the golden-ratio lattice (1, g), g the integer nearest n/phi coprime to n",
      .min_dim = 2,
      .max_dim = 2,
      .flags = {.index_addressable = true},
      .properties = {"rank-1 lattice", "Latin (one point per row and column)"},
      .randomization = {RandomizerFamily::rotation, Randomizer::none},
      .counts = "any n >= 1: the classic Fibonacci lattice for n = 1, 2, 3, 5, 8, 13, ..., 987, 1597, ...; "
                "strict=1 accepts only those",
      .params = {params::flag("strict", "1: accept only Fibonacci numbers n (the classic construction)", "0")},
      .validate =
          [](const SamplerRequest& request) {
            if (request.values.flag("strict"))
              require(fibonacci_index(*request.n) != 0, "n", *request.n,
                      "with strict=1 n must be a Fibonacci number (1, 2, 3, 5, 8, 13, 21, ...; nearest: " +
                          nearby_fibonacci(*request.n) + ")");
          },
      .count = requested_count,
      .generate = generate_rotated(fibonacci_of),
      .bind = bind_rotated(fibonacci_of),
      .seeded = seeded_rotated(fibonacci_of),
  });

  list.push_back({
      .name = "lattice",
      .kind = "pattern",
      .description = "rank-1 lattice frac(i z / n) (Korobov 1959; Sloan, Joe 1994): z from generator=, or "
                     "Korobov's (1, a, a^2, ...) mod n from a=, or else the Korobov a minimizing the worst-case "
                     "error in the weighted Korobov space (alpha = 2, weights gamma^j; P_2 of Sloan, Joe 1994)",
      .min_dim = 1,
      .max_dim = Rank1Lattice::max_dimensions,
      .flags = {.index_addressable = true},
      .properties = {"rank-1 lattice", "Latin in every coordinate with gcd(z_j, n) = 1 (always for a= and the search)"},
      .randomization = {RandomizerFamily::rotation, Randomizer::none},
      .counts = "any n >= 1; the Korobov search (no generator=, no a=) takes n x d <= 2^26",
      .params = {params::integers("generator", "generating vector z: d integers in [1, n)", "", at_least(1),
                                  {1, Rank1Lattice::max_dimensions}),
                 params::integer("a", "Korobov parameter in [1, n), coprime to n: z = (1, a, a^2, ...) mod n", "",
                                 at_least(1)),
                 params::real("gamma", "product-weight decay of the search criterion, gamma_j = gamma^j", "1",
                              left_open(0, 1))},
      .validate =
          [](const SamplerRequest& request) {
            param_gamma(request);
            if (!explicit_generator(request))
              require(*request.n <= search_limit / request.d, "n", *request.n,
                      "the Korobov search takes n x d <= 2^26 (here d = " + std::to_string(request.d) +
                          "); give a= or generator= for larger lattices");
          },
      .count = requested_count,
      .generate = generate_rotated(lattice_of),
      .bind = bind_rotated(lattice_of),
      .seeded = seeded_rotated(lattice_of),
  });

  list.push_back({
      .name = "kronecker",
      .kind = "sequence",
      .description = "Kronecker (additive recurrence, Weyl) sequence frac(s + i alpha); by default alpha = R_d, the "
                     "powers of 1/phi_d, phi_d the root of x^(d+1) = x + 1 (Roberts 2018); exact for every index",
      .min_dim = 1,
      .max_dim = Kronecker::max_dimensions,
      .flags = {.index_addressable = true, .progressive = true},
      .properties = {"low-discrepancy", "three gap lengths per coordinate"},
      .randomization = {RandomizerFamily::rotation, Randomizer::none},
      .counts = "any n >= 1",
      .params = {params::reals("alpha", "d reals, one per dimension (default: R_d of Roberts 2018)", "", open(0, 1),
                               {1, Kronecker::max_dimensions}),
                 params::real("offset", "the offset s added in every dimension", "0", half_open(0, 1))},
      .validate = [](const SamplerRequest& request) { kronecker_from(request); },
      .count = requested_count,
      .generate = generate_rotated(kronecker_from),
      .bind = bind_rotated(kronecker_from),
      .seeded = seeded_rotated(kronecker_from),
  });

  list.push_back({
      .name = "lattice-sequence",
      .kind = "sequence",
      .description = "extensible rank-1 lattice sequence frac(phi_2(i) g) (Hickernell, Hong, L'Ecuyer, Lemieux "
                     "2000): every 2^m prefix is the lattice frac(k g / 2^m); default g: the first 32 components of "
                     "Cools, Kuo, Nuyens 2006's lattice-32001-1024-1048576.3600",
      .min_dim = 1,
      .max_dim = LatticeSequence::max_dimensions,
      .flags = {.index_addressable = true, .progressive = true},
      .properties = {"rank-1 lattice at n = 2^m",
                     "Latin at n = 2^m in every coordinate with odd g_j (all of the default)"},
      .randomization = {RandomizerFamily::rotation, Randomizer::none},
      .counts = "any n >= 1; lattices at n = 2^m (the default vector is built for 2^10 <= n <= 2^20)",
      .params = {params::integers("generator", "generating vector g: d integers (default: CKN 2006, d <= 32)", "",
                                  at_least(1), {1, LatticeSequence::max_dimensions})},
      .validate = [](const SamplerRequest& request) { lattice_sequence_from(request); },
      .count = requested_count,
      .generate = generate_rotated(lattice_sequence_from),
      .bind = bind_rotated(lattice_sequence_from),
      .seeded = seeded_rotated(lattice_sequence_from),
  });

  return list;
}

}  // namespace stratum::registry_families
