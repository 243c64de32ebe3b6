// Reads a program's metrics JSON (a flat object of numbers, written by
// odelab::Metrics::toJson) with nlohmann-json, so the checks read it with a
// parser of their own rather than the programs' writer's twin.
#pragma once

#include <nlohmann/json.hpp>

#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>

#include "Metrics.h"

namespace checks {

// Throws std::runtime_error naming the file on a missing file, malformed
// JSON, or a value that is not a number. null is a non-finite value: the
// writer has no other way to say NaN or infinity in JSON.
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
      metrics.set(name, std::numeric_limits<double>::quiet_NaN());
    else if (value.is_number())
      metrics.set(name, value.get<double>());
    else
      throw std::runtime_error("metrics JSON " + path + ": " + name + " is not a number");
  }
  return metrics;
}

}  // namespace checks
