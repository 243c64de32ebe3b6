#pragma once

// Exit statuses shared by every test program, so that scripts (the CTest
// checks, the lab) can tell a usage mistake from a physics failure.
namespace odelab::exit_code {
constexpr int OK = 0;
constexpr int RUNTIME_ERROR = 1;   // I/O failure or other unexpected error
constexpr int USAGE = 2;           // invalid option or value; nothing written
constexpr int BLEW_UP = 3;         // simulation state became non-finite
constexpr int ODE_ERROR = 4;       // ODE reported an error through dError/dDebug
constexpr int MISSING_RESOURCE = 5;  // shaders, font or the window module not found
constexpr int NO_DISPLAY = 6;      // a window was needed but none could be opened
// The engine --engine or --compare named failed, not its physics: its
// process died or was killed, it answered what is not the protocol, or it
// missed a request's deadline (peers/engines/EnginePipe.h). The output
// files' last line names it; no blow-up is counted (non_finite stays 0).
constexpr int ENGINE_FAILED = 7;
}  // namespace odelab::exit_code
