#include "rgbd_core/Interrupt.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstring>
#include <mutex>

namespace hrgbd {
namespace {

volatile sig_atomic_t g_signal = 0;

/** Fixed slots the handler may read: a path is written while its slot is Filling, then Used. */
constexpr int kSlots = 64;
constexpr std::size_t kPathMax = 4096;
enum Slot : int { Free, Filling, Used };
std::atomic<int> g_state[kSlots];
char g_paths[kSlots][kPathMax];

std::mutex g_mutex;
std::vector<std::string> g_not_written;

void say(const char* text) {
  const auto n = std::strlen(text);
  if (write(STDERR_FILENO, text, n) < 0) return;  // nothing else to do in a handler
}

void onSignal(int sig) {
  if (g_signal == 0) {
    g_signal = sig;
    return;
  }
  // Second signal: the loops did not get to it; end now, without what is incomplete.
  int removed = 0;
  for (int k = 0; k < kSlots; ++k)
    if (g_state[k].load() == Used && unlink(g_paths[k]) == 0) ++removed;
  say(removed > 0 ? "\ninterrupted again: stopped at once; the temporary files of the outputs "
                    "not complete are removed, those outputs are not written\n"
                  : "\ninterrupted again: stopped at once; outputs not complete are not written\n");
  _exit(128 + sig);
}

}  // namespace

Interrupted::Interrupted(int signal)
    : std::runtime_error(signal == SIGTERM ? "terminated (SIGTERM)" : "interrupted (SIGINT)"),
      m_signal(signal) {}

void installInterruptHandlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    struct sigaction sa {};
    sa.sa_handler = onSignal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGTERM, &sa, nullptr);
  });
}

void checkInterrupt() {
  if (g_signal != 0) throw Interrupted(g_signal);
}

bool interrupted() { return g_signal != 0; }

int registerTemporary(const std::string& path) {
  if (path.size() >= kPathMax) return -1;
  for (int k = 0; k < kSlots; ++k) {
    int expected = Free;
    if (g_state[k].compare_exchange_strong(expected, Filling)) {
      std::memcpy(g_paths[k], path.c_str(), path.size() + 1);
      g_state[k].store(Used);
      return k;
    }
  }
  return -1;
}

void unregisterTemporary(int slot) {
  if (slot >= 0 && slot < kSlots) g_state[slot].store(Free);
}

void noteNotWritten(const std::string& what) {
  const std::lock_guard<std::mutex> lock(g_mutex);
  g_not_written.push_back(what);
}

std::vector<std::string> notWritten() {
  const std::lock_guard<std::mutex> lock(g_mutex);
  return g_not_written;
}

}  // namespace hrgbd
