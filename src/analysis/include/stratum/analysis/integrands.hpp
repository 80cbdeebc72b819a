#pragma once
/// The registry of test integrands over the unit cube [0,1]^d, each with its
/// exact integral: the 2D integrands of the lecture (§2–4: a disk, a
/// triangle, a step, a Gaussian, a bilinear product, a random edge) and the
/// six d-dimensional Genz families (Genz 1984, "Testing multidimensional
/// integration routines", in Tools, Methods and Languages for Scientific and
/// Engineering Computation, pp. 81–94; parameterized as in Surjanovic and
/// Bingham, Virtual Library of Simulation Experiments, sfu.ca/~ssurjano).
/// `stratum integrate`, `stratum converge`, `stratum.integrands()`, the
/// studies and the tests iterate over this list. Families live in
/// src/analysis/integrands_2d.cpp and src/analysis/integrands_genz.cpp.
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "stratum/registry/params.hpp"

namespace stratum::analysis {

/// Integrand parameters by name, each a flat list of numbers (as warps take
/// them): Genz `a` and `u` are one number (used in every dimension) or d.
using IntegrandParams = std::map<std::string, std::vector<double>>;

/// An integrand with its parameters and dimension validated once.
class Integrand {
 public:
  virtual ~Integrand() = default;
  virtual std::size_t dimension() const = 0;
  /// ∫_{[0,1]^d} f, from a closed form (or, for the corner peak, a 1D integral
  /// of a positive function by Boost's exp-sinh quadrature; see its entry).
  virtual double exact() const = 0;
  /// values[i] = f(row i of points), points row-major n × dimension(). No checks:
  /// callers go through evaluate_integrand or have checked the points themselves.
  virtual void evaluate(const double* points, std::size_t n, double* values) const = 0;
};

struct IntegrandInfo {
  std::string name;         ///< "disk", "step", "genz-oscillatory", ...
  std::string description;  ///< the formula and its source, one line
  unsigned min_dim = 1;
  unsigned max_dim = 1;
  unsigned default_dim = 2;
  std::vector<std::string> properties;  ///< "smooth", "discontinuous", "indicator", "kink", ...
  std::vector<Param> params;            ///< numbers (reals or integers); every one has a default
  /// Builds the integrand for dimension d (already checked against
  /// [min_dim, max_dim]) and params (defaults filled in, names checked);
  /// throws stratum::invalid_argument naming a bad parameter value.
  std::function<std::unique_ptr<const Integrand>(unsigned d, const IntegrandParams&)> make;
};

/// Every integrand, in a stable order.
const std::vector<IntegrandInfo>& integrands();

/// The integrand called `name`; throws invalid_argument listing the valid names.
const IntegrandInfo& find_integrand(std::string_view name);

/// Checks d against the entry's range (d = 0: its default_dim), rejects
/// unknown parameter names and non-finite values, fills defaults, then makes.
std::unique_ptr<const Integrand> make_integrand(std::string_view name, unsigned d, const IntegrandParams& params = {});

/// Parameters given as text (the CLI's --integrand-param KEY=1,2.5,3), parsed
/// by the schema's one parser; throws invalid_argument naming the parameter.
IntegrandParams parse_integrand_params(std::string_view integrand, const std::map<std::string, std::string>& text);

/// f at each of n points of integrand.dimension() coordinates, after checking
/// every coordinate is finite and in [0,1] (the message names row and column).
std::vector<double> evaluate_integrand(const Integrand& integrand, const double* points, std::size_t n);

}  // namespace stratum::analysis
