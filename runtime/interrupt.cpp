// The interruption flag and the pending temporary file.
#include "interrupt.hpp"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstring>

namespace pd {

namespace {
std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "the flag is set from a signal handler");
// A fixed buffer: a signal handler cannot touch std::string. `g_pending` is set only
// after the path is complete, and cleared before the buffer changes.
char g_path[4096];
std::atomic<bool> g_pending{false};
}  // namespace

Interrupted::Interrupted(int signal, std::string where)
    : signal_(signal), message_("interrupted by " + signal_name(signal) + " " + std::move(where)) {}

void request_interrupt(int signal) noexcept {
  int none = 0;
  g_signal.compare_exchange_strong(none, signal);
}

int interrupt_signal() noexcept { return g_signal.load(); }

void clear_interrupt() noexcept { g_signal.store(0); }

void throw_if_interrupted(const std::string& where) {
  if (const int s = g_signal.load()) throw Interrupted(s, where);
}

void set_pending_temporary(const char* path) noexcept {
  g_pending.store(false);
  if (path == nullptr || std::strlen(path) >= sizeof g_path) return;
  std::strcpy(g_path, path);
  g_pending.store(true);
}

void remove_pending_temporary() noexcept {
  if (g_pending.exchange(false)) ::unlink(g_path);
}

std::string signal_name(int signal) {
  if (signal == SIGINT) return "SIGINT";
  if (signal == SIGTERM) return "SIGTERM";
  return "signal " + std::to_string(signal);
}

}  // namespace pd
