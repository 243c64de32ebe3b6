// Reads a program's metrics JSON (a flat object of numbers and a few lists of
// sentences, such as an engine run's translation_notes, written by
// odelab::Metrics::toJson) with nlohmann-json, so the checks read it with a
// parser of their own rather than the programs' writer's twin.
#pragma once

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "Metrics.h"

namespace checks {

// Throws std::runtime_error naming the file on a missing file, malformed
// JSON, or a value that is neither a number nor a list of strings. null is
// a metric not measured; the strings "nan", "inf" and "-inf" a measured
// value that is not finite (utils/Metrics.h, the writer's one rule). A list
// of strings is kept as texts (no bound can be set on it).
inline odelab::Metrics readMetricsFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("metrics JSON " + path + ": cannot read it");
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& error) {
    throw std::runtime_error("metrics JSON " + path + ": " + error.what());
  }
  if (!document.is_object()) throw std::runtime_error("metrics JSON " + path + ": not an object");
  odelab::Metrics metrics;
  for (const auto& [name, value] : document.items()) {
    if (value.is_null())
      metrics.setNotMeasured(name);
    else if (value == "nan")
      metrics.set(name, std::numeric_limits<double>::quiet_NaN());
    else if (value == "inf" || value == "-inf")
      metrics.set(name, value == "inf" ? std::numeric_limits<double>::infinity()
                                       : -std::numeric_limits<double>::infinity());
    else if (value.is_number())
      metrics.set(name, value.get<double>());
    else if (value.is_array() && std::all_of(value.begin(), value.end(), [](const auto& v) { return v.is_string(); }))
      metrics.setTexts(name, value.get<std::vector<std::string>>());
    else
      throw std::runtime_error("metrics JSON " + path + ": " + name + " is neither a number nor a list of strings");
  }
  return metrics;
}

}  // namespace checks
