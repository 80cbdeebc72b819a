// The fields of `compare --configs` and stratum.compare(configs=...): keys,
// types and ranges, read without the registry, so the fuzz target
// (fuzz/configs.cpp) reaches them; parse_configs (compare.cpp) adds the
// sampler spec and validate_settings.
#include <cstdint>
#include <string>

#include "stratum/io/json.hpp"
#include "stratum/render/compare.hpp"
#include "stratum/util/error.hpp"

namespace stratum::render {

std::vector<CompareConfig> read_configs(const nlohmann::json& configs, const RenderSettings& defaults) {
  if (!configs.is_array() || configs.empty())
    throw invalid_argument("configs", io::json_excerpt(configs), "must be a non-empty JSON array");
  std::vector<CompareConfig> result;
  for (std::size_t i = 0; i < configs.size(); ++i) {
    const auto& c = configs[i];
    const std::string where = "configs[" + std::to_string(i) + "]";
    if (!c.is_object()) throw invalid_argument(where, io::json_excerpt(c), "must be an object");
    CompareConfig config{"config " + std::to_string(i), defaults};
    RenderSettings& s = config.settings;
    for (const auto& item : c.items()) {
      const std::string& key = item.key();
      const auto& v = item.value();
      auto text = [&] {
        if (!v.is_string()) throw invalid_argument(where + "." + key, io::json_excerpt(v), "must be a string");
        return v.get<std::string>();
      };
      auto count = [&] {
        if (!v.is_number_unsigned() || v.get<std::uint64_t>() < 1 || v.get<std::uint64_t>() > (1u << 24))
          throw invalid_argument(where + "." + key, io::json_excerpt(v), "must be an integer in [1, 2^24]");
        return v.get<std::uint32_t>();
      };
      if (key == "label") config.label = text();
      else if (key == "integrator") s.integrator = text();
      else if (key == "light_strategy") s.light_strategy = text();
      else if (key == "hemisphere") s.hemisphere = text();
      else if (key == "sampler") s.sampler.sampler = text();
      else if (key == "randomize") s.sampler.randomize = text();
      else if (key == "time_pattern") s.sampler.time_pattern = text();
      else if (key == "spp") s.sampler.spp = count();
      else if (key == "light_samples") s.light_samples = count();
      else if (key == "max_depth") s.max_depth = count();
      else if (key == "pixel_centers") {
        if (!v.is_boolean()) throw invalid_argument(where + "." + key, io::json_excerpt(v), "must be true or false");
        s.pixel_centers = v.get<bool>();
      } else
        throw invalid_argument(where + "." + key, "(unknown key)",
                               "allowed keys are label, integrator, spp, light_samples, light_strategy, hemisphere, "
                               "sampler, randomize, time_pattern, max_depth, pixel_centers");
    }
    result.push_back(std::move(config));
  }
  return result;
}

}  // namespace stratum::render
