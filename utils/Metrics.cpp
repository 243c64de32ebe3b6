#include "Metrics.h"

#include "SafeFile.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace odelab {

void Metrics::set(const std::string& name, double value) {
  const auto [found, added] = index_.emplace(name, entries_.size());
  if (added)
    entries_.emplace_back(name, value);
  else
    entries_[found->second].second = value;
}

bool Metrics::has(const std::string& name) const { return index_.count(name) != 0; }

double Metrics::get(const std::string& name) const {
  const auto found = index_.find(name);
  return found == index_.end() ? std::numeric_limits<double>::quiet_NaN() : entries_[found->second].second;
}

namespace {
// JSON has no NaN or infinity; such a metric is written as null.
std::string formatNumber(double value) {
  if (!std::isfinite(value)) return "null";
  std::ostringstream out;
  // Whole numbers (counts, hashes) print exactly; the rest to 10 digits.
  if (value == std::floor(value) && std::fabs(value) < 9007199254740992.0)
    out << std::fixed << std::setprecision(0) << value;
  else
    out << std::setprecision(10) << value;
  return out.str();
}
}  // namespace

void Metrics::print(std::ostream& out) const {
  for (const auto& [name, value] : entries_) out << name << " = " << formatNumber(value) << '\n';
}

std::string Metrics::toJson() const {
  std::string json = "{";
  for (size_t i = 0; i < entries_.size(); ++i) {
    json += (i ? ",\n  \"" : "\n  \"") + entries_[i].first + "\": " + formatNumber(entries_[i].second);
  }
  json += "\n}\n";
  return json;
}

void Metrics::writeJsonAtomically(const std::string& path) const { writeFileAtomically(path, toJson()); }

Metrics parseMetricsJson(const std::string& text) {
  Metrics metrics;
  size_t pos = 0;
  auto fail = [&](const char* what) {
    throw std::runtime_error(std::string("metrics JSON: ") + what + " at offset " + std::to_string(pos));
  };
  auto skipSpace = [&] {
    while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
  };
  skipSpace();
  if (pos >= text.size() || text[pos] != '{') fail("expected '{'");
  ++pos;
  skipSpace();
  if (pos < text.size() && text[pos] == '}') return metrics;
  while (true) {
    skipSpace();
    if (pos >= text.size() || text[pos] != '"') fail("expected a quoted name");
    const size_t end = text.find('"', pos + 1);
    if (end == std::string::npos) fail("unterminated name");
    const std::string name = text.substr(pos + 1, end - pos - 1);
    pos = end + 1;
    skipSpace();
    if (pos >= text.size() || text[pos] != ':') fail("expected ':'");
    ++pos;
    skipSpace();
    double value;
    if (text.compare(pos, 4, "null") == 0) {
      value = std::numeric_limits<double>::quiet_NaN();
      pos += 4;
    } else {
      const char* begin = text.c_str() + pos;
      char* stop = nullptr;
      value = std::strtod(begin, &stop);
      if (stop == begin) fail("expected a number");
      pos += static_cast<size_t>(stop - begin);
    }
    metrics.set(name, value);
    skipSpace();
    if (pos < text.size() && text[pos] == ',') {
      ++pos;
      continue;
    }
    if (pos < text.size() && text[pos] == '}') return metrics;
    fail("expected ',' or '}'");
  }
}

}  // namespace odelab
