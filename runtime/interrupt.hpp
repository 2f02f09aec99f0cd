// Cooperative interruption (SIGINT/SIGTERM): the signal handler only records the signal;
// long loops (Newton iterations, Krylov iterations, dynamics steps, file writes) poll it
// and throw Interrupted at a point where stopping leaves no partial file behind.
#pragma once

#include <exception>
#include <string>

namespace pd {

// Not a std::runtime_error on purpose: code that turns runtime errors into "the solve
// failed" messages (Newton's linear-solve fallback) must let an interruption through.
class Interrupted : public std::exception {
 public:
  Interrupted(int signal, std::string where);
  const char* what() const noexcept override { return message_.c_str(); }
  int signal() const { return signal_; }

 private:
  int signal_;
  std::string message_;
};

// Async-signal-safe: records the signal (the first one wins).
void request_interrupt(int signal) noexcept;
// The recorded signal, 0 when none.
int interrupt_signal() noexcept;
// Forgets a recorded signal (tests; a new run in the same process).
void clear_interrupt() noexcept;
// Throws Interrupted naming `where` when a signal was recorded.
void throw_if_interrupted(const std::string& where);
inline void throw_if_interrupted(const char* where) {
  if (interrupt_signal() != 0) throw_if_interrupted(std::string(where));
}

// The temporary file being written (write_file_atomically), so a second signal, which
// ends the process at once, can still remove it. Both are async-signal-safe to read.
void set_pending_temporary(const char* path) noexcept;  // nullptr: none
void remove_pending_temporary() noexcept;               // unlink(2) it, if any

// "SIGINT", "SIGTERM", or "signal N".
std::string signal_name(int signal);

}  // namespace pd
