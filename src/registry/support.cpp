#include "support.hpp"

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include <sys/mman.h>

#include <algorithm>

#include "stratum/util/error.hpp"
#include "stratum/util/interrupt.hpp"

namespace stratum::registry_support {

std::optional<std::string> param_text(const SamplerRequest& request, const std::string& name) {
  if (auto it = request.params.find(name); it != request.params.end()) return it->second;
  return std::nullopt;
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
