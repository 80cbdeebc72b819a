#pragma once
/// Wraps a core triad (sample / pdf / invert on std::array points) as a
/// registry Warp over row-major arrays. Header-local (anonymous namespace):
/// each family source instantiates its own.
#include <array>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include "stratum/util/error.hpp"
#include "stratum/warp_registry.hpp"

namespace stratum::registry_families {
namespace {

/// A 1-element value: 1D triads take and return a double, not an array.
template <unsigned D>
using WarpPoint = std::conditional_t<D == 1, double, std::array<double, D>>;

template <unsigned D>
WarpPoint<D> load_point(const double* x) {
  if constexpr (D == 1) {
    return x[0];
  } else {
    std::array<double, D> p;
    for (unsigned k = 0; k < D; ++k) p[k] = x[k];
    return p;
  }
}
template <unsigned D>
void store_point(const WarpPoint<D>& p, double* x) {
  if constexpr (D == 1) x[0] = p;
  else
    for (unsigned k = 0; k < D; ++k) x[k] = p[k];
}

/// Core: an object with sample(WarpPoint<In>) -> WarpPoint<Out>,
/// pdf(WarpPoint<Out>) -> double and invert(WarpPoint<Out>) -> WarpPoint<In>.
template <unsigned In, unsigned Out, class Core>
class TriadWarp final : public Warp {
 public:
  explicit TriadWarp(Core core) : core_(std::move(core)) {}
  unsigned input_dim() const override { return In; }
  unsigned output_dim() const override { return Out; }
  void sample(const double* u, std::size_t n, double* out) const override {
    for (std::size_t i = 0; i < n; ++i) store_point<Out>(core_.sample(load_point<In>(u + i * In)), out + i * Out);
  }
  void pdf(const double* p, std::size_t n, double* out) const override {
    for (std::size_t i = 0; i < n; ++i) out[i] = core_.pdf(load_point<Out>(p + i * Out));
  }
  void invert(const double* p, std::size_t n, double* u) const override {
    for (std::size_t i = 0; i < n; ++i) store_point<In>(core_.invert(load_point<Out>(p + i * Out)), u + i * In);
  }

 private:
  Core core_;
};

template <unsigned In, unsigned Out, class Core>
std::unique_ptr<const Warp> make_triad(Core core) {
  return std::make_unique<TriadWarp<In, Out, Core>>(std::move(core));
}

/// A parameter-free triad from three function pointers.
template <class SampleFn, class PdfFn, class InvertFn>
struct FunctionTriad {
  SampleFn sample_fn;
  PdfFn pdf_fn;
  InvertFn invert_fn;
  template <class P>
  auto sample(const P& u) const {
    return sample_fn(u);
  }
  template <class P>
  double pdf(const P& p) const {
    return pdf_fn(p);
  }
  template <class P>
  auto invert(const P& p) const {
    return invert_fn(p);
  }
};
template <class S, class P, class I>
FunctionTriad<S, P, I> function_triad(S s, P p, I i) {
  return {s, p, i};
}

/// A parameter's single number (the registry has filled defaults).
inline double scalar_param(const WarpParams& params, const std::string& name) {
  const auto& value = params.at(name);
  require(value.size() == 1, name, to_message_string(value.size()) + " numbers", "takes exactly one number");
  return value[0];
}

}  // namespace
}  // namespace stratum::registry_families
