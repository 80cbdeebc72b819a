// Fuzz target: the sampler spec grammar NAME[(KEY=VALUE,...)][:RANDOMIZER]
// (registry/spec.hpp): parse, format, parse again gives the same spec; and
// the comma-separated lists of specs and KEY=VALUE items.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "stratum/registry.hpp"
#include "stratum/registry/spec.hpp"
#include "stratum/util/error.hpp"

// The grammar is fuzzed without the registry (its samplers would take
// minutes to build here). spec.cpp's look-ups of sampler names are defined
// to trap: the functions called below never reach them, and if one did the
// fuzzer would report it as a crash.
namespace stratum {
const std::vector<SamplerInfo>& samplers() { __builtin_trap(); }
const SamplerInfo& find_sampler(std::string_view) { __builtin_trap(); }
}  // namespace stratum

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const stratum::SamplerSpec spec = stratum::parse_sampler_spec_syntax(text);
    const stratum::SamplerSpec again = stratum::parse_sampler_spec_syntax(stratum::format_sampler_spec(spec));
    if (again.name != spec.name || again.params != spec.params || again.randomize != spec.randomize) __builtin_trap();
  } catch (const stratum::invalid_argument&) {
  }
  try {
    stratum::split_sampler_list(text);
  } catch (const stratum::invalid_argument&) {
  }
  try {
    stratum::parse_key_value("param", text);
  } catch (const stratum::invalid_argument&) {
  }
  try {
    stratum::parse_uint64("n", text);
  } catch (const stratum::invalid_argument&) {
  }
  return 0;
}
