/// The default rank tiles of sobol-bn, pmj02-bn and lattice-bn:
/// data/blue-noise/BASE-bn-default.bin, as written by `stratum optimize
/// blue-noise --base BASE` (docs/blue-noise.md gives the commands), embedded
/// at build time by cmake/embed_binary.cmake.
#include <cstddef>
#include <string>
#include <string_view>

#include "stratum/sequences/ranked_blue_noise.hpp"

namespace stratum {
namespace embedded {
extern const unsigned char blue_noise_sobol_table[], blue_noise_pmj02_table[], blue_noise_lattice_table[];
extern const std::size_t blue_noise_sobol_table_size, blue_noise_pmj02_table_size, blue_noise_lattice_table_size;
}  // namespace embedded

namespace {
BlueNoiseTable parse_embedded(const unsigned char* bytes, std::size_t size, BlueNoiseBase base) {
  const std::string name = std::string("data/blue-noise/") + blue_noise_base_name(base) + "-bn-default.bin";
  BlueNoiseTable table = parse_blue_noise_table(std::string_view(reinterpret_cast<const char*>(bytes), size), name);
  require(table.base == base, "table", name, "holds a tile of another base");
  return table;
}
}  // namespace

const BlueNoiseTable& default_blue_noise_table(BlueNoiseBase base) {
  using namespace embedded;
  static const BlueNoiseTable sobol =
      parse_embedded(blue_noise_sobol_table, blue_noise_sobol_table_size, BlueNoiseBase::sobol);
  static const BlueNoiseTable pmj02 =
      parse_embedded(blue_noise_pmj02_table, blue_noise_pmj02_table_size, BlueNoiseBase::pmj02);
  static const BlueNoiseTable lattice =
      parse_embedded(blue_noise_lattice_table, blue_noise_lattice_table_size, BlueNoiseBase::lattice);
  switch (base) {
    case BlueNoiseBase::pmj02:
      return pmj02;
    case BlueNoiseBase::lattice:
      return lattice;
    default:
      return sobol;
  }
}

}  // namespace stratum
