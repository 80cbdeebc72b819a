#include "interruptible.hpp"

#include <csignal>
#include <mutex>

#include "stratum/util/interrupt.hpp"

namespace stratum::python {

namespace {

std::mutex scopes_mutex;
int scopes = 0;                     // live InterruptScopes
bool chained = false;               // our handler is installed
struct sigaction python_action {};  // the handler it hands the signal on to

extern "C" void stop_and_chain(int signal, siginfo_t* info, void* context) {
  request_interrupt();
  if (python_action.sa_flags & SA_SIGINFO) python_action.sa_sigaction(signal, info, context);
  else if (python_action.sa_handler != SIG_DFL && python_action.sa_handler != SIG_IGN) python_action.sa_handler(signal);
}

}  // namespace

InterruptScope::InterruptScope() {
  const std::lock_guard lock(scopes_mutex);
  if (scopes++ > 0) return;
  clear_interrupt();  // a request from before this call is not for it
  struct sigaction current {};
  if (::sigaction(SIGINT, nullptr, &current) != 0) return;
  const bool function =
      (current.sa_flags & SA_SIGINFO) || (current.sa_handler != SIG_DFL && current.sa_handler != SIG_IGN);
  if (!function) return;  // ignored, or the default (the process ends): as the user set it
  python_action = current;
  struct sigaction action {};
  action.sa_sigaction = stop_and_chain;
  action.sa_flags = SA_SIGINFO | (current.sa_flags & SA_ONSTACK);
  sigemptyset(&action.sa_mask);
  chained = ::sigaction(SIGINT, &action, nullptr) == 0;
}

InterruptScope::~InterruptScope() {
  const std::lock_guard lock(scopes_mutex);
  if (--scopes > 0) return;
  if (chained) ::sigaction(SIGINT, &python_action, nullptr);
  chained = false;
}

void register_interrupted(pybind11::module_&) {
  pybind11::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const interrupted&) {
      // Python's handler noted the signal: run it now (KeyboardInterrupt by
      // default, or the user's handler and what it raises).
      if (PyErr_CheckSignals() == 0 && !PyErr_Occurred()) PyErr_SetNone(PyExc_KeyboardInterrupt);
    }
  });
}

}  // namespace stratum::python
