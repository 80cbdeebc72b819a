// Uses the header-only core directly and the registry by name.
#include <cstdio>
#include <stratum/registry.hpp>
#include <stratum/sequences/halton.hpp>

int main() {
  const stratum::Halton halton(2);
  const double x = halton.sample(5, 0);
  stratum::SamplerRequest request;
  request.n = 8;
  request.d = 2;
  request.randomize = "none";
  const stratum::PointSet points = stratum::generate_points("halton", request);
  std::printf("consumer: halton(5, 0) = %g, registry gave %zu points\n", x, points.n);
  return (x == 0.625 && points.n == 8 && points(5, 0) == 0.625) ? 0 : 1;
}
