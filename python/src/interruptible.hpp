#pragma once
/// Ctrl-C during a long call: KeyboardInterrupt, as in pure Python.
///
/// A long call runs with the GIL released, so Python's own SIGINT handler
/// only notes the signal (its Python-level handler runs when the call
/// returns). An InterruptibleRelease releases the GIL and, for the call,
/// puts a handler in front of Python's that also asks the library to stop
/// (stratum::request_interrupt; the library's loops call check_interrupt),
/// then hands the signal on to Python's handler. The library unwinds with
/// stratum::interrupted, which module.cpp translates by running Python's
/// signal handlers (KeyboardInterrupt by default).
#include <pybind11/pybind11.h>

#include <optional>

namespace stratum::python {

/// Puts the chaining SIGINT handler in place for its lifetime (nested and
/// concurrent calls share one); Python's handler is back afterwards. Where
/// SIGINT is ignored or has its default action, nothing changes.
class InterruptScope {
 public:
  InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;
  ~InterruptScope();
};

/// An InterruptScope and the GIL released (in that order; the GIL is taken
/// back before the handler is restored).
class InterruptibleRelease {
 public:
  InterruptibleRelease() { release_.emplace(); }
  ~InterruptibleRelease() { release_.reset(); }

 private:
  InterruptScope scope_;
  std::optional<pybind11::gil_scoped_release> release_;
};

/// Registers the translation of stratum::interrupted into Python's signal
/// handling (KeyboardInterrupt).
void register_interrupted(pybind11::module_& m);

}  // namespace stratum::python
