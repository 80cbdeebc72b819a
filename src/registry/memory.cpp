#include "stratum/memory.hpp"

#include <unistd.h>

#include <atomic>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#include "stratum/util/error.hpp"

namespace stratum {

namespace {

/// MemAvailable in bytes (Linux 3.14+), or 0 where /proc/meminfo lacks it.
std::uint64_t mem_available() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::uint64_t kib = 0;
  std::string unit;
  while (meminfo >> key >> kib >> unit)
    if (key == "MemAvailable:") return kib * 1024;
  return 0;
}

/// mem_available() read at most once per 50 ms: the guard runs on every
/// request, and the renderer makes one per pixel, dimension and shading
/// point, where reading /proc/meminfo each time (open, read, parse, close:
/// microseconds) cost more than the points themselves.
std::uint64_t mem_available_recent() {
  using Clock = std::chrono::steady_clock;
  static std::atomic<std::uint64_t> value{0};
  static std::atomic<Clock::rep> read_at{0};
  const Clock::rep now = Clock::now().time_since_epoch().count();
  const Clock::rep last = read_at.load(std::memory_order_acquire);
  if (last != 0 && now - last < std::chrono::duration_cast<Clock::duration>(std::chrono::milliseconds(50)).count())
    return value.load(std::memory_order_relaxed);
  const std::uint64_t available = mem_available();
  value.store(available, std::memory_order_relaxed);
  read_at.store(now, std::memory_order_release);
  return available;
}

std::uint64_t half_physical_memory() {
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return std::uint64_t{1} << 33;
  return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page_size) / 2;
}

}  // namespace

std::uint64_t memory_available() {
  std::uint64_t available = mem_available_recent();
  if (available == 0) available = half_physical_memory();
  if (const char* text = std::getenv("STRATUM_MEMORY_LIMIT"); text && *text) {
    std::uint64_t limit = 0;
    const char* end = text + std::strlen(text);
    const auto [stop, error] = std::from_chars(text, end, limit);
    if (error != std::errc() || stop != end)
      throw invalid_argument("STRATUM_MEMORY_LIMIT", text, "must be a byte count (an integer such as 1073741824)");
    if (limit < available) available = limit;
  }
  return available;
}

std::string format_bytes(double bytes) {
  static const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int unit = 0;
  while (bytes >= 1024 && unit < 6) bytes /= 1024, ++unit;
  char text[64];
  std::snprintf(text, sizeof text, unit == 0 ? "%.0f %s" : "%.1f %s", bytes, units[unit]);
  return text;
}

void require_memory(double bytes, std::string_view what) {
  const std::uint64_t available = memory_available();
  if (!(bytes <= static_cast<double>(available)))
    throw memory_error("needs " + format_bytes(bytes) + " for " + std::string(what) + ", " +
                       format_bytes(static_cast<double>(available)) + " available");
}

}  // namespace stratum
