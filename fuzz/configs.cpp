// Fuzz target: the JSON layer of `compare --configs` and stratum.compare
// (io::parse_json, with its nesting and size limits and its excerpts of bad
// values in messages); the configurations' fields are read by compare.cpp.
#include <cstddef>
#include <cstdint>
#include <string>

#include "stratum/io/json.hpp"
#include "stratum/util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const nlohmann::json configs = stratum::io::parse_json(text, "configs", "fuzz.json");
    const std::string excerpt = stratum::io::json_excerpt(configs);
    if (excerpt.size() > 200) __builtin_trap();  // messages show a short excerpt, never the whole value
    if (configs.is_array())
      for (const auto& config : configs) stratum::io::json_excerpt(config, 40);
  } catch (const stratum::invalid_argument&) {
  }
  return 0;
}
