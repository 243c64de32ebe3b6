#pragma once

namespace odelab {

// SIGINT, SIGTERM and SIGHUP ask a run to stop rather than kill it: the step loops
// (headless and window) end at the next step, the output files get an
// "# incomplete: stopped by SIGTERM ..." line, no metrics JSON is written,
// and the program exits with 128 + the signal's number (130, 143, 129), as a
// shell reports a process killed by it. SDL's own handlers, which would turn
// the signal into an ordinary window close (status 0), are switched off.
void installStopSignalHandlers();
// The signal that asked for a stop, or 0.
int stopSignal();
// "SIGINT", "SIGTERM", or "signal N".
const char* stopSignalName();

}  // namespace odelab
