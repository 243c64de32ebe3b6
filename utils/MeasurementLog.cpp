#include "MeasurementLog.h"

#include <cstdio>

#include "FormatValue.h"
#include "LineText.h"

namespace odelab {

namespace {

std::string formatted(const char* format, double value) {
  char text[40];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

}  // namespace

void MeasurementLog::open(const std::string& path, const std::string& title,
                          const std::vector<std::pair<std::string, std::string>>& settings,
                          const std::vector<std::string>& columns) {
  rows_ = 0;
  finished_ = false;
  file_.open(path);
  // Given text (a title, a setting's value, a comment, an end line's reason) kept to its one line.
  std::string head = "# " + lineText(title) + "\n";
  for (const auto& [key, value] : settings) head += "# " + lineText(key) + ": " + lineText(value) + "\n";
  // The column names are the first line that is not a comment, so the file
  // loads as a table: pandas.read_csv(f, sep='\t', comment='#'), gnuplot's
  // columnheaders.
  std::string header;
  for (const auto& column : columns) header += (header.empty() ? "" : "\t") + column;
  file_.write(head + header + "\n");
}

void MeasurementLog::row(const std::vector<double>& values) {
  if (!file_.isOpen()) return;
  std::string line;
  for (size_t i = 0; i < values.size(); ++i) line += formatted(i ? "\t%.10g" : "%.10g", values[i]);
  file_.write(line + "\n");
  ++rows_;
}

void MeasurementLog::comment(double time, const std::string& text) {
  file_.write("# " + timeStamp(time) + ": " + lineText(text) + "\n");
}

void MeasurementLog::finish(const std::string& line) {
  if (!file_.isOpen() || finished_) return;
  finished_ = true;
  file_.write("# " + lineText(line) + "\n");
}

void MeasurementLog::close() { file_.close(); }

std::string timeStamp(double simulatedTime) { return "t=" + formatValue(simulatedTime) + " s"; }

std::string joinPath(const std::string& folder, const std::string& name) {
  if (folder.empty() || folder == ".") return name;
  return folder.back() == '/' ? folder + name : folder + "/" + name;
}

}  // namespace odelab
