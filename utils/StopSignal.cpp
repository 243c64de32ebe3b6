#include "StopSignal.h"

#include <csignal>
#include <string>

#include "Platform.h"

namespace odelab {

volatile std::sig_atomic_t detail::stopSignalReceived = 0;

namespace {
extern "C" void onStopSignal(int signal) {
  // A second signal while the first is being handled kills as usual, so a
  // stuck run can still be ended.
  if (detail::stopSignalReceived != 0) {
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  detail::stopSignalReceived = signal;
}
}  // namespace

void installStopSignalHandlers() { platform::onStopRequest(onStopSignal); }

const char* stopSignalName() {
  switch (detail::stopSignalReceived) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
#ifdef SIGHUP
    case SIGHUP: return "SIGHUP";
#endif
#ifdef SIGUSR1
    case SIGUSR1: return "SIGUSR1";
    case SIGUSR2: return "SIGUSR2";
    case SIGALRM: return "SIGALRM";
#endif
    default: return "a signal";
  }
}

}  // namespace odelab
