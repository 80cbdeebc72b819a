#pragma once
/// A request to stop long work: Ctrl-C in the CLI (io::StopOnInterrupt),
/// KeyboardInterrupt in Python. Long loops (measures, studies, sampler
/// generation, the renderer's tiles) call check_interrupt() between pieces
/// of work small enough that a request is honoured within a fraction of a
/// second; the work then unwinds with stratum::interrupted.
///
/// The flag is process-wide because signals are: a signal handler sets it,
/// so it is a lock-free atomic (async-signal-safe) and nothing else.
#include <atomic>
#include <stdexcept>
#include <string>

namespace stratum {

/// Thrown by check_interrupt(): the work was asked to stop (not an error in its input).
class interrupted : public std::runtime_error {
 public:
  explicit interrupted(const std::string& what = "interrupted") : std::runtime_error(what) {}
};

namespace detail {
static_assert(std::atomic<bool>::is_always_lock_free, "a signal handler sets the interrupt flag");
inline std::atomic<bool> interrupt_flag{false};
}  // namespace detail

/// The flag itself, for APIs that take a stop flag (render::render).
inline const std::atomic<bool>& interrupt_flag() noexcept { return detail::interrupt_flag; }
/// Asks running work to stop; async-signal-safe.
inline void request_interrupt() noexcept { detail::interrupt_flag.store(true, std::memory_order_relaxed); }
inline bool interrupt_requested() noexcept { return detail::interrupt_flag.load(std::memory_order_relaxed); }
/// Forgets a request (before new work starts).
inline void clear_interrupt() noexcept { detail::interrupt_flag.store(false, std::memory_order_relaxed); }
/// Throws stratum::interrupted when a stop was requested.
inline void check_interrupt() {
  if (interrupt_requested()) throw interrupted();
}

}  // namespace stratum
