#pragma once

// A child process spoken to in lines: its stdin and stdout are pipes of
// ours, its stderr is ours. NodeEngine.cpp runs the Node.js engine server
// through it (doc/engine-protocol.md). Started with posix_spawnp, never
// through a shell; a write to a child that has gone fails with an error
// instead of killing the program with SIGPIPE.

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

  // false when the child no longer reads (it ended, or closed its stdin).
  bool writeLine(const std::string& line);
  // The next line without its newline; false at the end of its output.
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
  void reap(bool wait);
  void finish();  // closes its stdin and waits for it, killing it after a grace time
};

}  // namespace odelab::engines
