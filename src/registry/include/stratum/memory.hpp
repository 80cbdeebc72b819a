#pragma once
/// The memory guard: an operation that would allocate more than is available
/// is refused before it allocates, with a message naming what it needs and
/// what there is ("needs 24.0 GiB for ..., 11.7 GiB available"). Sampler
/// generation, the measures, the renderer and the studies each count what
/// they allocate (the points and their own buffers) and ask require_memory.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

namespace stratum {

/// Thrown by require_memory (the CLI exits 3; Python raises MemoryError).
class memory_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Bytes one operation may allocate: the memory available now (MemAvailable
/// of /proc/meminfo: what can be allocated without swapping; half the
/// physical memory where that is unknown), at most STRATUM_MEMORY_LIMIT
/// bytes when that environment variable is set (docs/outputs.md; a value that
/// is not a byte count is an invalid_argument naming it).
std::uint64_t memory_available();

/// Throws memory_error unless `bytes` fit in memory_available(); `what` says
/// what they are for ("2000000 x 4 points of sobol", ...).
void require_memory(double bytes, std::string_view what);

/// A size for messages: "512 B", "3.5 KiB", "24.0 GiB".
std::string format_bytes(double bytes);

}  // namespace stratum
