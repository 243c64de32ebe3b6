#include "StopSignal.h"

#include <csignal>
#include <string>

namespace odelab {

namespace {
volatile std::sig_atomic_t received = 0;

extern "C" void onStopSignal(int signal) {
  // A second signal while the first is being handled kills as usual, so a
  // stuck run can still be ended.
  if (received != 0) {
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  received = signal;
}
}  // namespace

void installStopSignalHandlers() {
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
#ifdef SIGHUP
  // The terminal or session went away: a stop like the others (129), not a
  // kill that leaves the output files unmarked. Ignored stays ignored (nohup).
  struct sigaction hangup {};
  if (sigaction(SIGHUP, nullptr, &hangup) == 0 && hangup.sa_handler != SIG_IGN) sigaction(SIGHUP, &action, nullptr);
#endif
}

int stopSignal() { return received; }

const char* stopSignalName() {
  switch (received) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
#ifdef SIGHUP
    case SIGHUP: return "SIGHUP";
#endif
    default: return "a signal";
  }
}

}  // namespace odelab
