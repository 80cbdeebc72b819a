#include "support.hpp"

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include <sys/mman.h>

#include <algorithm>
#include <charconv>
#include <sstream>

#include "stratum/util/error.hpp"
#include "stratum/util/interrupt.hpp"

namespace stratum::registry_support {

std::optional<std::string> param_text(const SamplerRequest& request, const std::string& name) {
  if (auto it = request.params.find(name); it != request.params.end()) return it->second;
  return std::nullopt;
}

static std::int64_t parse_int(const std::string& name, const std::string& text) {
  std::int64_t value = 0;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end)
    throw invalid_argument(name, text.empty() ? "''" : text, "must be an integer");
  return value;
}

std::optional<std::int64_t> param_int(const SamplerRequest& request, const std::string& name) {
  auto text = param_text(request, name);
  if (!text) return std::nullopt;
  return parse_int(name, *text);
}

bool param_bool(const SamplerRequest& request, const std::string& name, bool fallback) {
  auto text = param_text(request, name);
  if (!text) return fallback;
  std::string t = *text;
  std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (t == "1" || t == "true" || t == "yes" || t == "on") return true;
  if (t == "0" || t == "false" || t == "no" || t == "off") return false;
  throw invalid_argument(name, *text, "must be a boolean (1/0, true/false, yes/no)");
}

std::optional<std::vector<std::int64_t>> param_int_list(const SamplerRequest& request, const std::string& name) {
  auto text = param_text(request, name);
  if (!text) return std::nullopt;
  std::vector<std::int64_t> values;
  std::stringstream stream(*text);
  std::string item;
  while (std::getline(stream, item, ',')) values.push_back(parse_int(name, item));
  if (values.empty()) throw invalid_argument(name, "''", "must be a comma-separated list of integers");
  return values;
}

/// Large buffers ask Linux for transparent huge pages: first-touch page
/// faults on 4 KiB pages otherwise cost more than computing the points.
static void advise_huge_pages(double* data, std::size_t count) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t page = 4096;
  const std::size_t bytes = count * sizeof(double);
  if (bytes < (std::size_t{8} << 20)) return;
  const auto begin = (reinterpret_cast<std::uintptr_t>(data) + page - 1) & ~(page - 1);
  const auto end = reinterpret_cast<std::uintptr_t>(data) + bytes;
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)data;
  (void)count;
#endif
}

PointSet allocate_points(std::size_t n, std::size_t d) {
  PointSet points;
  points.n = n;
  points.d = d;
  points.data.reset(new double[n * d]);  // default-initialized: no zero pass
  advise_huge_pages(points.data.get(), n * d);
  return points;
}

void parallel_rows(std::uint64_t n, unsigned threads, const std::function<void(std::uint64_t, std::uint64_t)>& fill) {
  constexpr std::uint64_t chunk = 4096;
  if (threads <= 1 || n <= chunk) {
    // In pieces, so that a stop request (stratum/util/interrupt.hpp) is seen
    // between them: rows are independent, the result is the same.
    constexpr std::uint64_t piece = std::uint64_t{1} << 18;
    for (std::uint64_t first = 0; first < n; first += piece) {
      if (first > 0) check_interrupt();  // not before the first: a small fill never throws it
      fill(first, std::min(n, first + piece));
    }
    return;
  }
  oneapi::tbb::task_arena arena(static_cast<int>(threads));
  arena.execute([&] {
    oneapi::tbb::parallel_for(
        oneapi::tbb::blocked_range<std::uint64_t>(0, n, chunk),
        [&](const oneapi::tbb::blocked_range<std::uint64_t>& range) {
          check_interrupt();
          fill(range.begin(), range.end());
        },
        oneapi::tbb::simple_partitioner());
  });
}

}  // namespace stratum::registry_support
