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
class Metrics {
 public:
  void set(const std::string& name, double value);  // replaces an existing entry
  bool has(const std::string& name) const;
  double get(const std::string& name) const;  // NaN when absent
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
  std::vector<std::pair<std::string, double>> entries_;
  std::vector<std::pair<std::string, std::vector<std::string>>> texts_;
  // name -> position in entries_: 100,000 marks in a session stay fast.
  std::unordered_map<std::string, size_t> index_;
};

// Parses a flat JSON object of numbers, nulls and arrays of strings (as written by
// Metrics::toJson; null reads as NaN); throws std::runtime_error "metrics
// JSON: ..." with the line and column of malformed input, or naming the
// metric whose value is not a number.
Metrics parseMetricsJson(const std::string& text);

}  // namespace odelab
