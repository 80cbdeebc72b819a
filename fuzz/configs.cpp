// Fuzz target: `compare --configs` and stratum.compare(configs=...) as far
// as they go without the renderer: the JSON layer (io::parse_json, with its
// nesting and size limits and the short excerpts of bad values in
// messages), then the configurations' fields (render::read_configs: keys,
// JSON types, integer ranges). What it accepts must be in range; what it
// refuses must be a message, never a crash.
#include <cstddef>
#include <cstdint>
#include <string>

#include "stratum/io/json.hpp"
#include "stratum/render/compare.hpp"
#include "stratum/util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const nlohmann::json configs = stratum::io::parse_json(text, "configs", "fuzz.json");
    const std::string excerpt = stratum::io::json_excerpt(configs);
    if (excerpt.size() > 200) __builtin_trap();  // messages show a short excerpt, never the whole value
    if (configs.is_array())
      for (const auto& config : configs) stratum::io::json_excerpt(config, 40);
    const auto read = stratum::render::read_configs(configs, stratum::render::RenderSettings{});
    if (read.empty() || read.size() != configs.size()) __builtin_trap();
    for (const auto& config : read) {
      const auto& s = config.settings;
      const auto in_range = [](std::uint32_t v) { return v >= 1 && v <= (1u << 24); };
      if (!in_range(s.sampler.spp) || !in_range(s.light_samples) || !in_range(s.max_depth)) __builtin_trap();
    }
  } catch (const stratum::invalid_argument& error) {
    if (std::string(error.what()).size() > 4096) __builtin_trap();  // a message, not the input echoed
  }
  return 0;
}
