#pragma once

// A child process spoken to in lines: its stdin and stdout are pipes of
// ours, its stderr is ours. NodeEngine.cpp runs the Node.js engine server
// through it (doc/engine-protocol.md). Started with posix_spawnp, never
// through a shell; a write to a child that has gone fails with an error
// instead of killing the program with SIGPIPE.
//
// No wait is without an end: each request has a deadline (setDeadline),
// and a stop signal (SIGINT, SIGTERM, SIGHUP: StopSignal.h) is acted on
// within a tenth of a second while the child is waited for. Either ends the
// child at once (SIGKILL) and reaps it; the read or write then fails and
// endedHow() says which of them it was.

#include <chrono>
#include <string>
#include <sys/types.h>
#include <vector>

namespace odelab::engines {

class EnginePipe {
 public:
  // Starts `argv[0]` (found on PATH when it has no slash) with `argv`.
  // Throws std::runtime_error when it cannot be started.
  explicit EnginePipe(const std::vector<std::string>& argv);
  ~EnginePipe();  // closes its stdin, waits for it (kills it after a grace time): no zombie
  EnginePipe(const EnginePipe&) = delete;
  EnginePipe& operator=(const EnginePipe&) = delete;

  // The next writes and reads must be done within `seconds` from now (the
  // deadline the caller scaled to the work it asks for).
  void setDeadline(double seconds);
  // false when the child no longer reads (it ended, or closed its stdin),
  // or the deadline passed, or a stop signal came.
  bool writeLine(const std::string& line);
  // The next line without its newline; false at the end of its output, or
  // when the deadline passed, or a stop signal came.
  bool readLine(std::string& line);
  // After readLine or writeLine failed: how the child ended, in words
  // ("exit status 1", "killed by signal 9"); waits for it (kills it if it
  // has not ended a few seconds after its stdin closed).
  std::string endedHow();

 private:
  pid_t pid_ = -1;
  int toChild_ = -1;    // the child's stdin
  int fromChild_ = -1;  // the child's stdout
  std::string buffer_;  // read and not yet returned
  bool reaped_ = false;
  int status_ = 0;
  double deadlineSeconds_ = 0;  // as set, for the message
  std::chrono::steady_clock::time_point deadline_ = std::chrono::steady_clock::time_point::max();
  std::string cutOff_;  // why this side ended the child ("" when it ended by itself)
  void reap(bool wait);
  // Waits until `fd` is ready for `events` (poll), in slices short enough to
  // see a stop signal; false (the child killed and reaped, cutOff_ saying
  // why) when the deadline passes or a stop signal comes first.
  bool waitReady(int fd, short events, const char* doing);
  void kill(const std::string& why);
  void finish();  // closes its stdin and waits for it, killing it after a grace time
};

}  // namespace odelab::engines
