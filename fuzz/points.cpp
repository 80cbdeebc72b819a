// Fuzz target: the strict point-file reader (io::read_points_strict) on
// text, CSV and .npy. The first byte picks the format; the rest is the file.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "stratum/io/read_points.hpp"
#include "stratum/util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char* extensions[] = {".txt", ".csv", ".npy"};
  const std::string path = "/tmp/stratum-fuzz-points-" + std::to_string(::getpid()) + extensions[data[0] % 3];
  {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  try {
    const stratum::PointSet points = stratum::io::read_points_strict(path);
    // A set it accepts is whole: n rows of d finite coordinates.
    if (points.n == 0 || points.d == 0) __builtin_trap();
    for (std::size_t i = 0; i < points.n * points.d; ++i)
      if (!(points.data[i] == points.data[i] && points.data[i] - points.data[i] == 0)) __builtin_trap();
  } catch (const stratum::invalid_argument&) {  // refused with a message: fine
  }
  ::unlink(path.c_str());
  return 0;
}
