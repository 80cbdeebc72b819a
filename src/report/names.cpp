/// Words for the page: registry specs ("sobol:owen") as the names a reader
/// knows ("Owen-scrambled Sobol'"), counted nouns ("1 point", "16 points")
/// and durations that never read "0.0 s".
#include <fmt/core.h>

#include <cmath>
#include <map>

#include "sections.hpp"
#include "stratum/registry.hpp"

namespace stratum::report {

namespace {

std::string base_name(const std::string& sampler) {
  static const std::map<std::string, std::string> names{
      {"random", "random"},
      {"grid", "regular grid"},
      {"jittered", "jittered"},
      {"multi-jittered", "multi-jittered"},
      {"cmj", "correlated multi-jittered"},
      {"n-rooks", "N-rooks"},
      {"n-queens", "N-queens"},
      {"latin-square", "Latin square"},
      {"zaremba", "Zaremba"},
      {"pmj02", "PMJ02"},
      {"poisson-disk", "Poisson disk"},
      {"best-candidate", "best candidate"},
      {"halton", "Halton"},
      {"hammersley", "Hammersley"},
      {"sobol", "Sobol'"},
      {"zero-two", "(0,2)-sequence"},
      {"fibonacci", "Fibonacci lattice"},
      {"lattice", "rank-1 lattice"},
  };
  const auto found = names.find(sampler);
  return found == names.end() ? sampler : found->second;
}

/// The randomizer a choice with an empty one gets: the registry's default.
std::string resolved_randomizer(const std::string& sampler, const std::string& randomize) {
  if (!randomize.empty()) return randomize;
  for (const auto& info : samplers())
    if (info.name == sampler) return info.randomizers.empty() ? "none" : info.randomizers.front();
  return "none";
}

bool default_is_none(const std::string& sampler) { return resolved_randomizer(sampler, "") == "none"; }

}  // namespace

std::string sampler_spec(const std::string& sampler, const std::string& randomize) {
  return randomize.empty() ? sampler : sampler + ":" + randomize;
}

std::string sampler_name(const std::string& sampler, const std::string& randomize) {
  const std::string base = base_name(sampler);
  const std::string r = resolved_randomizer(sampler, randomize);
  if (r == "none") return default_is_none(sampler) ? base : "unscrambled " + base;
  if (r == "owen") return "Owen-scrambled " + base;
  if (r == "owen-hash") return "hash-Owen-scrambled " + base;
  if (r == "xor") return base + " with a digital shift";
  if (r == "lms") return base + " with linear matrix scrambling";
  if (r == "permute") return base + " with random digit permutations";
  if (r == "cp") return base + " with Cranley–Patterson rotation";
  return base + " (" + r + ")";
}

std::string sampler_name(const analysis::SamplerChoice& choice) { return sampler_name(choice.name, choice.randomize); }

std::string sampler_spec(const analysis::SamplerChoice& choice) { return sampler_spec(choice.name, choice.randomize); }

std::string named_with_spec(const analysis::SamplerChoice& choice) {
  return sampler_name(choice) + " `" + sampler_spec(choice) + "`";
}

std::string capitalized(std::string text) {
  if (!text.empty() && text[0] >= 'a' && text[0] <= 'z') text[0] = static_cast<char>(text[0] - 'a' + 'A');
  return text;
}

std::string counted(std::uint64_t count, const std::string& singular, const std::string& plural) {
  return fmt::format("{} {}", count, count == 1 ? singular : (plural.empty() ? singular + "s" : plural));
}

std::string format_seconds(double seconds) {
  if (!(seconds >= 0.001)) return "under 1 ms";
  if (seconds < 1) return fmt::format("{:.0f} ms", seconds * 1000);
  return format_number(seconds, 3) + " s";
}

}  // namespace stratum::report
