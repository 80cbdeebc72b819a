/// sobol-bn's default key tile: data/blue-noise/sobol-bn-default.bin, as
/// written by `stratum optimize blue-noise` (docs/blue-noise.md gives the
/// command), embedded at build time by cmake/embed_binary.cmake.
#include <cstddef>
#include <string_view>

#include "stratum/sequences/sobol_bn.hpp"

namespace stratum {
namespace embedded {
extern const unsigned char blue_noise_default_table[];
extern const std::size_t blue_noise_default_table_size;
}  // namespace embedded

const BlueNoiseTable& default_blue_noise_table() {
  static const BlueNoiseTable table =
      parse_blue_noise_table(std::string_view(reinterpret_cast<const char*>(embedded::blue_noise_default_table),
                                              embedded::blue_noise_default_table_size),
                             "data/blue-noise/sobol-bn-default.bin");
  return table;
}

}  // namespace stratum
