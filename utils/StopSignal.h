#pragma once

#include <csignal>

namespace odelab {

// SIGINT, SIGTERM and SIGHUP (and on POSIX SIGUSR1, SIGUSR2 and SIGALRM) ask
// a run to stop rather than kill it: the step loops
// (headless and window) end at the next step, the output files get an
// "# incomplete: stopped by SIGTERM ..." line, no metrics JSON is written,
// and the program exits with 128 + the signal's number (130, 143, 129, 138,
// 142), as a shell reports a process killed by it. SIGPIPE and SIGXFSZ are
// ignored: a write they would have ended fails instead, and says so. SDL's own handlers, which would turn
// the signal into an ordinary window close (status 0), are switched off.
void installStopSignalHandlers();
namespace detail {
extern volatile std::sig_atomic_t stopSignalReceived;  // StopSignal.cpp's handler sets it
}
// The signal that asked for a stop, or 0. Inline: the step loops read it every step.
inline int stopSignal() { return detail::stopSignalReceived; }
// "SIGINT", "SIGTERM", or "signal N".
const char* stopSignalName();

}  // namespace odelab
