#include "MeasurementLog.h"

#include "FormatValue.h"
#include "SafeFile.h"

#include <cerrno>
#include <cstring>
#include <exception>
#include <stdexcept>

namespace odelab {

MeasurementLog::~MeasurementLog() {
  if (file_) std::fclose(file_);
}

void MeasurementLog::open(const std::string& path, const std::string& title,
                          const std::vector<std::pair<std::string, std::string>>& settings,
                          const std::vector<std::string>& columns) {
  close();
  path_ = path;
  rows_ = 0;
  finished_ = false;
  file_ = openExclusiveOutput(path);
  check(std::fprintf(file_, "# %s\n", title.c_str()));
  for (const auto& [key, value] : settings) check(std::fprintf(file_, "# %s: %s\n", key.c_str(), value.c_str()));
  // The column names are the first line that is not a comment, so the file
  // loads as a table: pandas.read_csv(f, sep='\t', comment='#'), gnuplot's
  // columnheaders.
  std::string header;
  for (const auto& column : columns) header += (header.empty() ? "" : "\t") + column;
  check(std::fprintf(file_, "%s\n", header.c_str()));
  check(std::fflush(file_));
}

void MeasurementLog::row(const std::vector<double>& values) {
  if (!file_) return;
  for (size_t i = 0; i < values.size(); ++i) check(std::fprintf(file_, i ? "\t%.10g" : "%.10g", values[i]));
  check(std::fputc('\n', file_));
  check(std::fflush(file_));
  ++rows_;
}

void MeasurementLog::comment(double time, const std::string& text) {
  if (!file_) return;
  check(std::fprintf(file_, "# %s: %s\n", timeStamp(time).c_str(), text.c_str()));
  check(std::fflush(file_));
}

void MeasurementLog::finish(const std::string& line) {
  if (!file_ || finished_) return;
  finished_ = true;
  check(std::fprintf(file_, "# %s\n", line.c_str()));
  check(std::fflush(file_));
}

void MeasurementLog::close() {
  std::FILE* file = file_;
  file_ = nullptr;
  // fclose writes what is buffered and releases the lock; a failure there
  // is a lost row, reported like any other (not from the destructor).
  if (file && std::fclose(file) != 0 && !std::uncaught_exceptions()) check(-1);
}

void MeasurementLog::check(int result) {
  if (result < 0) throw std::runtime_error("cannot write '" + path_ + "': " + std::strerror(errno));
}

std::string timeStamp(double simulatedTime) { return "t=" + formatValue(simulatedTime) + " s"; }

std::string joinPath(const std::string& folder, const std::string& name) {
  if (folder.empty() || folder == ".") return name;
  return folder.back() == '/' ? folder + name : folder + "/" + name;
}

}  // namespace odelab
