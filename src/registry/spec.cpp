#include "stratum/registry/spec.hpp"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <thread>

#include <sched.h>

#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"

namespace stratum {

namespace {

constexpr std::string_view grammar = "write NAME[(KEY=VALUE,...)][:RANDOMIZER], e.g. sobol:owen (docs/samplers.md)";

/// A parsed spec with the 1-based positions its parts started at, for the
/// registry checks' messages.
struct Located {
  SamplerSpec spec;
  std::map<std::string, std::size_t> key_position;
  std::size_t randomize_position = 0;
};

std::string shown(std::string_view text) { return text.empty() ? std::string("''") : std::string(text); }

[[noreturn]] void refuse(std::string_view text, const std::string& why) {
  throw invalid_argument("sampler", shown(text), why);
}

std::string at(std::size_t index) { return "at position " + std::to_string(index + 1); }

bool name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
}

/// Checks that text[begin, end) is a NAME (letters, digits, '-', '_', '.').
void check_word(std::string_view text, std::size_t begin, std::size_t end, std::string_view what) {
  if (begin == end) {
    refuse(text, "empty " + std::string(what) + " " + at(begin) + "; " + std::string(grammar));
  }
  for (std::size_t i = begin; i < end; ++i)
    if (!name_char(text[i]))
      refuse(text, "unexpected '" + std::string(1, text[i]) + "' " + at(i) + " in the " + std::string(what) +
                       " (letters, digits, '-', '_', '.'); " + std::string(grammar));
}

Located parse_located(std::string_view text) {
  Located out;
  std::size_t i = 0;
  while (i < text.size() && text[i] != '(' && text[i] != ':' && text[i] != ')') ++i;
  check_word(text, 0, i, "sampler name");
  out.spec.name = std::string(text.substr(0, i));
  if (i < text.size() && text[i] == ')') refuse(text, "unbalanced parentheses: ')' " + at(i) + " has no '('");
  if (i < text.size() && text[i] == '(') {
    const std::size_t open = i;
    int depth = 0;
    std::size_t close = std::string_view::npos;
    for (std::size_t k = open; k < text.size(); ++k) {
      if (text[k] == '(') ++depth;
      if (text[k] == ')' && --depth == 0) {
        close = k;
        break;
      }
    }
    if (close == std::string_view::npos)
      refuse(text, "unbalanced parentheses: '(' " + at(open) + " is never closed; " + std::string(grammar));
    if (close == open + 1)
      refuse(text, "empty parameter list " + at(open) + "; leave out the parentheses or write (KEY=VALUE,...)");
    // Items split on the commas at depth 0 inside the parentheses; an item
    // without '=' continues the previous value (vector values).
    std::string last_key;
    std::size_t begin = open + 1;
    depth = 0;
    for (std::size_t k = open + 1; k <= close; ++k) {
      if (k < close && text[k] == '(') ++depth;
      if (k < close && text[k] == ')') --depth;
      if (k < close && (text[k] != ',' || depth > 0)) continue;
      const std::string_view item = text.substr(begin, k - begin);
      std::size_t equals = std::string_view::npos;
      for (std::size_t e = 0, d = 0; e < item.size(); ++e) {
        if (item[e] == '(') ++d;
        if (item[e] == ')') --d;
        if (item[e] == '=' && d == 0) {
          equals = e;
          break;
        }
      }
      if (equals == std::string_view::npos) {
        if (last_key.empty())
          refuse(text, "'" + std::string(item) + "' " + at(begin) + " is not KEY=VALUE; " + std::string(grammar));
        if (item.empty()) refuse(text, "empty value " + at(begin) + " in the value of key '" + last_key + "'");
        out.spec.params[last_key] += "," + std::string(item);
      } else {
        check_word(text, begin, begin + equals, "key");
        const std::string key(item.substr(0, equals));
        if (equals + 1 == item.size())
          refuse(text, "empty value for key '" + key + "' " + at(begin + equals + 1) + "; write KEY=VALUE");
        if (auto seen = out.key_position.find(key); seen != out.key_position.end())
          refuse(text, "duplicate key '" + key + "' " + at(begin) + " (first at position " +
                           std::to_string(seen->second) + "); give each key once");
        out.key_position[key] = begin + 1;
        out.spec.params[key] = std::string(item.substr(equals + 1));
        last_key = key;
      }
      begin = k + 1;
    }
    i = close + 1;
    if (i < text.size() && text[i] != ':')
      refuse(text, "unexpected '" + std::string(1, text[i]) + "' " + at(i) +
                       " after the parameters; only :RANDOMIZER may follow ')'");
  }
  if (i < text.size()) {  // text[i] == ':'
    const std::size_t begin = i + 1;
    std::size_t end = begin;
    while (end < text.size() && text[end] != '(' && text[end] != ')') ++end;
    if (begin == end && end == text.size())
      refuse(text, "empty randomizer after ':' " + at(i) + "; " + std::string(grammar));
    if (end < text.size() && text[end] == ')') refuse(text, "unbalanced parentheses: ')' " + at(end) + " has no '('");
    if (end < text.size())
      refuse(text, "unexpected '(' " + at(end) + " in the randomizer; parameters come before ':', " +
                       "as in lattice(generator=1,55,133):cp");
    check_word(text, begin, end, "randomizer");
    out.spec.randomize = std::string(text.substr(begin));
    out.randomize_position = begin + 1;
  }
  return out;
}

std::string join(const std::vector<std::string>& items) {
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

/// The registry names closest to `name`: within edit distance 2 (3 for long
/// names), or containing it, or contained in it; at most 5, nearest first.
std::vector<std::string> near_names(std::string_view name) {
  std::vector<std::pair<std::size_t, std::string>> scored;
  for (const auto& sampler : samplers()) {
    const std::size_t distance = edit_distance(name, sampler.name);
    const bool contains = name.size() >= 3 && (sampler.name.find(name) != std::string::npos ||
                                               name.find(sampler.name) != std::string_view::npos);
    if (distance <= (name.size() > 8 ? 3u : 2u) || contains) scored.emplace_back(distance, sampler.name);
  }
  std::stable_sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> names;
  for (std::size_t k = 0; k < scored.size() && k < 5; ++k) names.push_back(scored[k].second);
  return names;
}

const SamplerInfo& known_sampler(std::string_view text, const std::string& name) {
  for (const auto& sampler : samplers())
    if (sampler.name == name) return sampler;
  const auto near = near_names(name);
  std::vector<std::string> all;
  for (const auto& sampler : samplers()) all.push_back(sampler.name);
  refuse(text, "unknown sampler '" + name + "' at position 1; " +
                   (near.empty() ? "valid samplers are " + join(all)
                                 : "did you mean " + join(near) + "? (`stratum samplers` lists every sampler)"));
}

std::vector<std::string> param_names(const SamplerInfo& sampler) {
  std::vector<std::string> names;
  for (const auto& param : sampler.params) names.push_back(param.name);
  return names;
}

std::string takes(const SamplerInfo& sampler) {
  const auto names = param_names(sampler);
  return names.empty() ? sampler.name + " takes no parameters" : sampler.name + " takes " + join(names);
}

bool has_param(const SamplerInfo& sampler, const std::string& key) {
  const auto names = param_names(sampler);
  return std::find(names.begin(), names.end(), key) != names.end();
}

bool accepts(const SamplerInfo& sampler, const std::string& randomize) {
  return std::find(sampler.randomizers.begin(), sampler.randomizers.end(), randomize) != sampler.randomizers.end();
}

/// The registry checks of a parsed spec.
void check_located(std::string_view text, const Located& located) {
  const SamplerInfo& sampler = known_sampler(text, located.spec.name);
  for (const auto& [key, position] : located.key_position)
    if (!has_param(sampler, key))
      refuse(text, "unknown key '" + key + "' at position " + std::to_string(position) + "; " + takes(sampler));
  if (!located.spec.randomize.empty() && !accepts(sampler, located.spec.randomize))
    refuse(text, "randomizer '" + located.spec.randomize + "' at position " +
                     std::to_string(located.randomize_position) + " is not one " + sampler.name + " accepts; " +
                     sampler.name + " accepts " + join(sampler.randomizers));
}

std::string_view trim(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  return text;
}

}  // namespace

SamplerSpec parse_sampler_spec_syntax(std::string_view text) { return parse_located(text).spec; }

SamplerSpec parse_sampler_spec(std::string_view text) {
  Located located = parse_located(text);
  check_located(text, located);
  return std::move(located.spec);
}

std::string format_sampler_spec(const SamplerSpec& spec) {
  std::string text = spec.name;
  if (!spec.params.empty()) {
    text += '(';
    bool first = true;
    for (const auto& [key, value] : spec.params) {
      text += (first ? "" : ",") + key + "=" + value;
      first = false;
    }
    text += ')';
  }
  if (!spec.randomize.empty()) text += ":" + spec.randomize;
  return text;
}

std::vector<std::string> split_sampler_list(std::string_view text) {
  std::vector<std::string> items;
  // Unbalanced parentheses stay inside an item (an unclosed '(' takes the
  // rest of the list), so that the spec parser reports them as it does for
  // a single spec.
  int depth = 0;
  std::size_t begin = 0;
  for (std::size_t k = 0; k <= text.size(); ++k) {
    if (k < text.size() && text[k] == '(') ++depth;
    if (k < text.size() && text[k] == ')' && depth > 0) --depth;
    if (k < text.size() && (text[k] != ',' || depth > 0)) continue;
    const std::string_view item = trim(text.substr(begin, k - begin));
    if (item.empty())
      throw invalid_argument("samplers", shown(text),
                             "empty item " + at(begin) + "; write SPEC,SPEC,... (docs/samplers.md)");
    items.emplace_back(item);
    begin = k + 1;
  }
  return items;
}

std::vector<SamplerSpec> parse_sampler_list(std::string_view text) {
  std::vector<SamplerSpec> specs;
  for (const auto& item : split_sampler_list(text)) specs.push_back(parse_sampler_spec(item));
  return specs;
}

std::pair<std::string, std::string> parse_key_value(std::string_view option, std::string_view item) {
  const std::size_t equals = item.find('=');
  if (equals == std::string_view::npos || equals == 0 || equals + 1 == item.size())
    throw invalid_argument(option, shown(item), "must be written KEY=VALUE");
  return {std::string(item.substr(0, equals)), std::string(item.substr(equals + 1))};
}

std::map<std::string, std::string> parse_key_values(std::string_view option, const std::vector<std::string>& items) {
  std::map<std::string, std::string> values;
  for (const auto& item : items) {
    auto [key, value] = parse_key_value(option, item);
    if (values.count(key))
      throw invalid_argument(option, item, "conflicts with " + key + "=" + values.at(key) + "; give each key once");
    values[key] = value;
  }
  return values;
}

SamplerSpec combine_sampler_options(std::string_view text, const std::vector<std::string>& params,
                                    std::string_view randomize) {
  Located located = parse_located(text);
  check_located(text, located);
  SamplerSpec& spec = located.spec;
  const SamplerInfo& sampler = find_sampler(spec.name);
  std::map<std::string, std::string> given;
  for (const auto& item : params) {
    auto [key, value] = parse_key_value("param", item);
    if (spec.params.count(key))
      throw invalid_argument("param", item,
                             "conflicts with " + key + "=" + spec.params.at(key) + " in the sampler spec " +
                                 std::string(text) + "; give each parameter once");
    if (given.count(key))
      throw invalid_argument("param", item,
                             "conflicts with -p " + key + "=" + given.at(key) + "; give each parameter once");
    if (!has_param(sampler, key)) throw invalid_argument("param", item, takes(sampler));
    given[key] = value;
  }
  spec.params.insert(given.begin(), given.end());
  if (!randomize.empty()) {
    if (!spec.randomize.empty())
      throw invalid_argument("randomize", std::string(randomize),
                             "conflicts with the randomizer of the sampler spec " + std::string(text) +
                                 "; give it once, as NAME:RANDOMIZER or --randomize");
    if (!accepts(sampler, std::string(randomize)))
      throw invalid_argument("randomize", std::string(randomize),
                             sampler.name + " accepts " + join(sampler.randomizers));
    spec.randomize = std::string(randomize);
  }
  return std::move(spec);
}

std::uint64_t parse_uint64(std::string_view argument, std::string_view text) {
  std::uint64_t value = 0;
  const char* end = text.data() + text.size();
  const bool digits =
      !text.empty() && std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
  const auto [ptr, error] = std::from_chars(text.data(), end, value);
  if (!digits || error != std::errc() || ptr != end)
    throw invalid_argument(argument, shown(text), "must be an integer in [0, 2^64) = [0, 18446744073709551615]");
  return value;
}

std::uint64_t parse_seed(std::string_view text) { return parse_uint64("seed", text); }

namespace {

/// The whole text as a decimal unsigned, or nothing.
std::optional<unsigned> decimal(std::string_view text) {
  unsigned value = 0;
  const char* end = text.data() + text.size();
  const auto [next, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc{} || next != end) return std::nullopt;
  return value;
}

/// A whole decimal count > 0, or 0.
unsigned positive_count(std::string_view text) { return decimal(text).value_or(0); }

/// The CPUs this process may run on, or 0 where the mask cannot be read.
unsigned affinity_cpus() {
  cpu_set_t mask;
  CPU_ZERO(&mask);
  if (::sched_getaffinity(0, sizeof mask, &mask) != 0) return 0;
  return static_cast<unsigned>(CPU_COUNT(&mask));
}

}  // namespace

unsigned slurm_tasks_on_node(std::string_view list, unsigned node) {
  // Items "T" or "T(xR)" separated by commas: T tasks on each of R nodes.
  std::uint64_t first = 0;  // the first node of the item
  while (!list.empty()) {
    const std::string_view item = list.substr(0, list.find(','));
    list.remove_prefix(std::min(list.size(), item.size() + 1));
    const std::size_t open = item.find("(x");
    const unsigned tasks = positive_count(item.substr(0, open));
    unsigned repeat = 1;
    if (open != std::string_view::npos) {
      if (item.back() != ')') return 0;
      repeat = positive_count(item.substr(open + 2, item.size() - open - 3));
    }
    if (tasks == 0 || repeat == 0) return 0;
    if (node < first + repeat) return tasks;
    first += repeat;
  }
  return 0;
}

unsigned local_processes() {
  for (const char* name : {"OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS"})
    if (const char* text = std::getenv(name)) return std::max(1u, positive_count(text));
  const char* tasks = std::getenv("SLURM_STEP_TASKS_PER_NODE");
  const char* node = std::getenv("SLURM_NODEID");
  if (tasks && node && std::getenv("SLURM_STEP_ID"))  // inside an srun step, not just an allocation
    if (const std::optional<unsigned> index = decimal(node)) return std::max(1u, slurm_tasks_on_node(tasks, *index));
  return 1;
}

unsigned resolve_threads(std::int64_t threads) {
  require(threads >= 0 && threads <= max_threads, "threads", threads,
          "must be an integer in [0, " + std::to_string(max_threads) + "] (0: every core)");
  if (threads > 0) return static_cast<unsigned>(threads);
  // A launcher that binds a process (mpirun's --bind-to core, srun's
  // --cpu-bind, taskset) gives it its share of the cores already; unbound,
  // the processes of a job on one machine each take their share.
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const unsigned allowed = affinity_cpus();
  const unsigned share = allowed > 0 && allowed < cores ? allowed : cores / local_processes();
  return std::clamp(share, 1u, static_cast<unsigned>(max_threads));
}

}  // namespace stratum
