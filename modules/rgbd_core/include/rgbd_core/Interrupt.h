#pragma once
/** \file Interrupt.h
 * Ctrl-C (SIGINT) and SIGTERM during a run. The first signal is only noted: the work loops call
 * checkInterrupt() between frames, which throws Interrupted, and the unwinding removes what is
 * incomplete (OutputFile's temporary files, a rawlog's new image folder) like any other error;
 * the app then says what was not written and exits with 128 + the signal (130, 143). A second
 * signal, for a program stuck where no loop checks (waiting on a FIFO), ends it at once: the
 * handler removes the temporary files still registered (unlink(), async-signal-safe), says so
 * on stderr and calls _exit(128 + signal). */
#include <stdexcept>
#include <string>
#include <vector>

namespace hrgbd {

/** What checkInterrupt() throws once SIGINT or SIGTERM arrived. */
class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal);
  int signal() const { return m_signal; }
  /** 128 + the signal, as a shell reports a program the signal ended. */
  int exitCode() const { return 128 + m_signal; }

 private:
  int m_signal;
};

/** Installs the SIGINT and SIGTERM handlers (once per process; later calls do nothing). */
void installInterruptHandlers();

/** Throws Interrupted when a signal arrived since installInterruptHandlers(). */
void checkInterrupt();

/** Whether a signal arrived (for destructors, which must not throw). */
bool interrupted();

/** Registers a temporary file the handler removes when a second signal ends the program;
 * returns its slot (-1 when all are taken: the file is then removed only by unwinding). */
int registerTemporary(const std::string& path);
/** Forgets slot `slot` (the file was renamed into place or removed); -1 is ignored. */
void unregisterTemporary(int slot);

/** Notes an output not written because of the interrupt ("trajectory 't.txt'"), for the
 * app's last message; notWritten() returns them in order. */
void noteNotWritten(const std::string& what);
std::vector<std::string> notWritten();

}  // namespace hrgbd
