#include "StopSignal.h"

#include <csignal>
#include <string>

#include "Platform.h"

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

void installStopSignalHandlers() { platform::onStopRequest(onStopSignal); }

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
