#pragma once

#include <cstdio>
#include <string>

namespace odelab {

// The one writer of a run's streamed output files (Test2_output.txt,
// Test8_output.txt through MeasurementLog, <test>_run_log.txt through
// RunLog): opened through openExclusiveOutput (SafeFile.h), so they keep
// the one rule every file the project writes keeps (no link followed, no
// hard link, no FIFO or device, one run at a time), and each piece of text
// is written and flushed at once, so a crash loses at most the line being
// written. Every failure throws std::runtime_error "cannot write '<path>':
// <why>".
class StreamedFile {
 public:
  StreamedFile() = default;
  StreamedFile(const StreamedFile&) = delete;
  StreamedFile& operator=(const StreamedFile&) = delete;
  ~StreamedFile();  // closes quietly: a failure there has no one to tell

  // Creates or truncates `path` (closing the file open before).
  void open(const std::string& path);
  // Writes `text` as it is (its lines end in "\n") and flushes it.
  void write(const std::string& text);
  // Writes what is buffered and releases the file; a failure there is a
  // lost line, thrown like any other (unless an exception is unwinding).
  void close();
  bool isOpen() const { return file_ != nullptr; }
  const std::string& path() const { return path_; }

 private:
  [[noreturn]] void fail();

  std::FILE* file_ = nullptr;
  std::string path_;
};

}  // namespace odelab
