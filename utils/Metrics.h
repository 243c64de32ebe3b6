#pragma once

#include <ostream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace odelab {

// A flat, ordered set of named numbers (and a few named lists of sentences,
// such as an engine's translation notes): what a run measured. Printed as
// "name = value" lines and written as a flat JSON object of numbers, one a
// line, with the same digits: whole numbers exact, the rest to 10
// significant digits (Metrics.cpp, formatNumber, says why).
//
// One rule for a value that is not a finite number (doc/manual.md,
// "Outputs"). A metric the run did not measure (a period
// before a whole swing, an apex error before that bounce) is set with
// setNotMeasured: printed "name = not measured", written as JSON null, and
// null means that and nothing else. Any value given to set() was measured:
// a NaN or an infinity there (a blow-up, a division by zero) is written as
// the JSON string "nan", "inf" or "-inf", which no reader can take for a
// number or for a metric not measured yet; the lab refuses such a run,
// naming the metric.
class Metrics {
 public:
  void set(const std::string& name, double value);  // measured; replaces an existing entry
  void setNotMeasured(const std::string& name);     // replaces an existing entry; get() gives NaN
  // set(name, value) when `measured`, else setNotMeasured(name).
  void set(const std::string& name, double value, bool measured);
  // `name` as `from` has `fromName`, measured or not (copying a run's
  // metrics under another name keeps what was not measured so).
  void setAs(const std::string& name, const Metrics& from, const std::string& fromName);
  bool has(const std::string& name) const;
  bool measured(const std::string& name) const;  // false when absent or not measured
  double get(const std::string& name) const;  // NaN when absent or not measured
  const std::vector<std::pair<std::string, double>>& entries() const { return entries_; }
  // A list of sentences, written after the numbers as a JSON array of strings.
  void setTexts(const std::string& name, std::vector<std::string> texts);
  const std::vector<std::pair<std::string, std::vector<std::string>>>& texts() const { return texts_; }

  void print(std::ostream& out) const;
  std::string toJson() const;
  // Writes a unique temporary file beside `path` and renames it over `path`
  // (writeFileAtomically, SafeFile.h), so a reader never sees a half-written
  // file and two writers never mix. Throws std::runtime_error naming the path.
  void writeJsonAtomically(const std::string& path) const;

 private:
  size_t entry(const std::string& name, double value);  // its position, added or replaced
  std::vector<std::pair<std::string, double>> entries_;
  std::vector<bool> notMeasured_;  // beside entries_, one a name
  std::vector<std::pair<std::string, std::vector<std::string>>> texts_;
  // name -> position in entries_: 100,000 marks in a session stay fast.
  std::unordered_map<std::string, size_t> index_;
};

// Parses a flat JSON object of numbers, nulls and arrays of strings (as written by
// Metrics::toJson; null reads as not measured, "nan", "inf" and "-inf" as
// those measured values); throws std::runtime_error "metrics JSON: ..."
// with the line and column of malformed input, or naming the metric whose
// value is not a number.
Metrics parseMetricsJson(const std::string& text);

}  // namespace odelab
