#pragma once
/// Helpers shared by the registry's sampler families: parameter parsing,
/// point buffers and deterministic parallel filling.
#include <bit>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "stratum/randomizers/cranley_patterson.hpp"
#include "stratum/registry.hpp"

namespace stratum::registry_support {

/// A parameter as the user gave it, for messages (values are read from
/// request.values, bound to the schema).
std::optional<std::string> param_text(const SamplerRequest& request, const std::string& name);

/// An uninitialized n × d buffer.
PointSet allocate_points(std::size_t n, std::size_t d);

/// Calls fill(begin, end) over [0, n) in fixed chunks on `threads` threads
/// (oneTBB). Results are identical for any thread count as long as each row
/// depends only on its index.
void parallel_rows(std::uint64_t n, unsigned threads, const std::function<void(std::uint64_t, std::uint64_t)>& fill);

/// Fills an n × d PointSet from an index-addressable sample(index, dim).
template <class SampleFn>
PointSet fill_index_addressable(std::uint64_t n, unsigned d, unsigned threads, const SampleFn& sample) {
  PointSet points = allocate_points(n, d);
  double* out = points.data.get();
  parallel_rows(n, threads, [&](std::uint64_t begin, std::uint64_t end) {
    for (std::uint64_t i = begin; i < end; ++i)
      for (unsigned j = 0; j < d; ++j) out[i * d + j] = sample(i, j);
  });
  return points;
}

/// One construction per key, built on first use and shared: for the
/// constructions that depend on their dimensions only (Faure's matrices,
/// Sobol's tables, Kronecker's default vector), which a renderer binding a
/// generator per pixel and dimension would otherwise rebuild each time.
template <class T, class Key, class Make>
std::shared_ptr<const T> shared_construction(const Key& key, const Make& make) {
  static std::mutex mutex;
  static std::map<Key, std::shared_ptr<const T>> built;
  const std::lock_guard lock(mutex);
  auto& entry = built[key];
  if (!entry) entry = std::make_shared<const T>(make());
  return entry;
}

/// The generator of a shared construction (sample(index, dim)) as it is.
template <class Construction>
PointGenerator plain_generator(unsigned dimensions, std::shared_ptr<const Construction> shared) {
  return PointGenerator(dimensions, [shared](std::uint64_t i, unsigned j) { return shared->sample(i, j); });
}

/// A generator for a construction of the rotation or seeded family:
/// `construction.sample(index, dim)` composed with request.randomizer (cp: a
/// Cranley–Patterson rotation from the seed; none: as it is).
template <class Construction>
PointGenerator rotated_generator(const SamplerRequest& request, std::shared_ptr<const Construction> shared) {
  if (request.randomizer == Randomizer::cp)
    return PointGenerator(request.d, [shared, rotation = CranleyPattersonRotation(request.seed)](
                                         std::uint64_t i, unsigned j) { return rotation(shared->sample(i, j), j); });
  return plain_generator(request.d, std::move(shared));
}
template <class Construction>
PointGenerator rotated_generator(const SamplerRequest& request, Construction construction) {
  return rotated_generator(request, std::make_shared<const Construction>(std::move(construction)));
}

/// SamplerInfo::generate and SamplerInfo::bind of a rotation- or
/// seeded-family construction that `make(request)` builds: the same
/// composition twice, the bulk fill with the construction inlined (no call
/// through the generator per coordinate), the generator for one point at a time.
template <class Make>
auto generate_rotated(Make make) {
  return [make](const SamplerRequest& request) {
    const auto construction = make(request);
    const std::uint64_t start = request.start;
    if (request.randomizer == Randomizer::cp) {
      const CranleyPattersonRotation rotation(request.seed);
      return fill_index_addressable(*request.n, request.d, request.threads, [&](std::uint64_t i, unsigned j) {
        return rotation(construction.sample(start + i, j), j);
      });
    }
    return fill_index_addressable(*request.n, request.d, request.threads,
                                  [&](std::uint64_t i, unsigned j) { return construction.sample(start + i, j); });
  };
}
template <class Make>
auto bind_rotated(Make make) {
  return [make](const SamplerRequest& request) { return rotated_generator(request, make(request)); };
}

/// A construction that does not depend on the seed (grid, zaremba, kronecker,
/// lattice-sequence) as a SeededGenerator: built once per request; a seed's
/// state is its Cranley–Patterson shifts (cp; none: no state). The points of
/// rotated_generator.
template <class Construction>
class RotatedSeeded final : public SeededGenerator {
 public:
  RotatedSeeded(Construction construction, unsigned dimensions, bool rotate)
      : construction_(std::move(construction)), dimensions_(dimensions), rotate_(rotate) {}
  std::size_t state_words() const noexcept override { return rotate_ ? dimensions_ : 0; }
  void seed(std::uint64_t seed, unsigned coordinates, std::uint64_t* state) const noexcept override {
    if (!rotate_) return;
    const CranleyPattersonRotation rotation(seed);
    for (unsigned j = 0; j < coordinates; ++j) state[j] = std::bit_cast<std::uint64_t>(rotation.shift(j));
  }
  void point(const std::uint64_t* state, std::uint64_t index, unsigned coordinates,
             double* out) const noexcept override {
    for (unsigned j = 0; j < coordinates; ++j) {
      const double value = construction_.sample(index, j);
      out[j] = rotate_ ? CranleyPattersonRotation::rotate(value, std::bit_cast<double>(state[j])) : value;
    }
  }

 private:
  Construction construction_;
  unsigned dimensions_;
  bool rotate_;
};
/// SamplerInfo::seeded of such a construction (make(request) must not read the seed).
template <class Make>
auto seeded_rotated(Make make) {
  return [make](const SamplerRequest& request) -> std::shared_ptr<const SeededGenerator> {
    using Construction = std::decay_t<decltype(make(request))>;
    return std::make_shared<const RotatedSeeded<Construction>>(make(request), request.d,
                                                               request.randomizer == Randomizer::cp);
  };
}

/// SamplerInfo::keyed_pairs of a sampler whose 2D sets are `Pairs`
/// (patterns/keyed_pairs.hpp, included where this is used) under `randomizer`.
template <class Pairs, class Keyed = KeyedPairs>  // Keyed: complete only where this is used
auto keyed_under(Randomizer randomizer) {
  return [randomizer](Randomizer asked) -> std::optional<Keyed> {
    if (asked != randomizer) return std::nullopt;
    return Keyed{Pairs{}};
  };
}

/// SamplerInfo::count for samplers that return exactly the requested n.
inline std::optional<std::uint64_t> requested_count(const SamplerRequest& request) { return request.n; }

/// n is a power of two?
constexpr bool is_power_of_two(std::uint64_t n) { return n != 0 && (n & (n - 1)) == 0; }

}  // namespace stratum::registry_support
