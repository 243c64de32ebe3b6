#pragma once

#include <string>
#include <utility>
#include <vector>

#include "StreamedFile.h"

namespace odelab {

// A scene's output file (Test2_output.txt, Test8_output.txt): a header of
// "# key: value" lines naming every setting in force, a line of column names
// (the first line not starting with '#'), then tab-separated rows. Every row and comment is flushed at once, so a
// crash or kill loses at most the row being written. A run that ends
// normally adds a last line "# complete: ..." (finish); one cut short says
// "# incomplete: ..." when it still can, and a file with neither was cut
// short by a kill or a full disk. The file is written by StreamedFile, the
// one writer of streamed outputs (the one rule of SafeFile.h: no link or
// hard link written through, one run at a time).
class MeasurementLog {
 public:
  // Creates or truncates `path` and writes the header. Throws
  // std::runtime_error naming the path when it cannot be written, is not a
  // regular file, or another run holds it.
  void open(const std::string& path, const std::string& title,
            const std::vector<std::pair<std::string, std::string>>& settings, const std::vector<std::string>& columns);
  void row(const std::vector<double>& values);
  // A "# t=<time> s: text" line, e.g. an F-key change.
  void comment(double time, const std::string& text);
  // The last line: "complete: ..." or "incomplete: ..." (written once).
  void finish(const std::string& line);
  bool finished() const { return finished_; }
  void close();
  bool isOpen() const { return file_.isOpen(); }
  const std::string& path() const { return file_.path(); }
  long rows() const { return rows_; }

 private:
  StreamedFile file_;
  long rows_ = 0;
  bool finished_ = false;
};

// "t=1.234 s": how every change message names its simulated time.
std::string timeStamp(double simulatedTime);

// Joins a folder and a file name.
std::string joinPath(const std::string& folder, const std::string& name);

}  // namespace odelab
