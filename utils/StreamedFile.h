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
//
// A file opened while a StreamedFile::Hold is in force is held: nothing at
// its path is touched yet, and what is written to it is kept in memory
// until the hold is released (then the file is opened and given it) or
// ends without a release (then it is dropped, and the path keeps what a
// previous run left there).
class StreamedFile {
 public:
  // The streamed outputs a run is about to write are held while the run is
  // still being set up: every input read and every engine's scene built
  // (AbstractWindow's world creation, a compare run's every scene). A
  // refusal in that time (an engine that cannot build the scene, a file in
  // the way) leaves every output file as the previous run left it. Holds
  // nest: the outermost one decides. release() opens every held file, in
  // the order they were opened, and throws as open() does; a hold that ends
  // without release() (an exception, a refusal) drops them.
  class Hold {
   public:
    Hold();
    ~Hold();
    Hold(const Hold&) = delete;
    Hold& operator=(const Hold&) = delete;
    void release();

   private:
    bool released_ = false;
  };

  StreamedFile() = default;
  StreamedFile(const StreamedFile&) = delete;
  StreamedFile& operator=(const StreamedFile&) = delete;
  ~StreamedFile();  // closes quietly: a failure there has no one to tell

  // Creates or truncates `path` (closing the file open before); under a
  // hold, only once the hold is released.
  void open(const std::string& path);
  // Writes `text` as it is (its lines end in "\n") and flushes it.
  void write(const std::string& text);
  // Writes what is buffered and releases the file; a failure there is a
  // lost line, thrown like any other (unless an exception is unwinding).
  void close();
  // Open, or held and taking text: writes go somewhere.
  bool isOpen() const { return file_ != nullptr || held_; }
  const std::string& path() const { return path_; }

 private:
  [[noreturn]] void fail();
  void openNow();  // the path opened and the text kept while held written to it
  void forget();   // leaves the held files' list

  std::FILE* file_ = nullptr;
  std::string path_;
  bool held_ = false;
  std::string kept_;  // written while held
};

}  // namespace odelab
