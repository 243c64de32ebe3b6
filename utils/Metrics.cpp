#include "Metrics.h"

#include "SafeFile.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace odelab {

size_t Metrics::entry(const std::string& name, double value) {
  const auto [found, added] = index_.emplace(name, entries_.size());
  if (added) {
    entries_.emplace_back(name, value);
    notMeasured_.push_back(false);
  } else {
    entries_[found->second].second = value;
  }
  return found->second;
}

void Metrics::set(const std::string& name, double value) { notMeasured_[entry(name, value)] = false; }

void Metrics::setNotMeasured(const std::string& name) {
  notMeasured_[entry(name, std::numeric_limits<double>::quiet_NaN())] = true;
}

void Metrics::set(const std::string& name, double value, bool measured) {
  if (measured)
    set(name, value);
  else
    setNotMeasured(name);
}

void Metrics::setAs(const std::string& name, const Metrics& from, const std::string& fromName) {
  if (from.has(fromName) && !from.measured(fromName))
    setNotMeasured(name);
  else
    set(name, from.get(fromName));
}

void Metrics::setTexts(const std::string& name, std::vector<std::string> texts) {
  for (auto& entry : texts_)
    if (entry.first == name) {
      entry.second = std::move(texts);
      return;
    }
  texts_.emplace_back(name, std::move(texts));
}

bool Metrics::has(const std::string& name) const { return index_.count(name) != 0; }

bool Metrics::measured(const std::string& name) const {
  const auto found = index_.find(name);
  return found != index_.end() && !notMeasured_[found->second];
}

double Metrics::get(const std::string& name) const {
  const auto found = index_.find(name);
  return found == index_.end() ? std::numeric_limits<double>::quiet_NaN() : entries_[found->second].second;
}

namespace {
// A metric's text, in the "name = value" lines and the JSON file alike:
// whole numbers (counts, hashes) every digit up to 2^64; the rest to 10
// significant digits. The checks and the lab compare these digits: a
// --seconds 1.5 run ends at 1.499999999999946 s and must read as 1.5
// (expect_metrics sim_seconds==1.5; windows_files.sh looks for
// "sim_seconds": 2). So the numbers are not nlohmann's: its writer gives
// every digit, and for about 1 number in 1000 (Grisu2) 17 digits where 10
// would do (2.538528487 as 2.5385284869999998).
// The one spelling of each value that is not a finite number, measured: in
// the "name = value" lines as it is, in JSON as a string of it. A metric
// not measured is NOT_MEASURED_TEXT in the lines and null in JSON.
const char* const NOT_MEASURED_TEXT = "not measured";
const char* const NOT_MEASURED_JSON = "null";
const char* nonFiniteText(double value) { return std::isnan(value) ? "nan" : value > 0 ? "inf" : "-inf"; }

std::string formatNumber(double value) {
  if (!std::isfinite(value)) return nonFiniteText(value);
  std::ostringstream out;
  if (value == std::floor(value) && std::fabs(value) < 18446744073709551616.0)
    out << std::fixed << std::setprecision(0) << value;
  else  // 10 digits would round the largest doubles up past the largest, to infinity
    out << std::setprecision(std::fabs(value) > 1.797693134e308 ? 17 : 10) << value;
  return out.str();
}

// In JSON, -0.0 as "-0.0": nlohmann and Python read "-0" as the integer 0,
// which loses the sign. NaN and infinities, which JSON lacks, as strings
// ("nan", "inf", "-inf"): never null, which says "not measured".
std::string jsonNumber(double value) {
  if (!std::isfinite(value)) return std::string("\"") + nonFiniteText(value) + "\"";
  return value == 0 && std::signbit(value) ? "-0.0" : formatNumber(value);
}

// A JSON string a measured value that is not finite was written as.
bool nonFiniteFromText(const std::string& text, double& value) {
  if (text == "nan") value = std::numeric_limits<double>::quiet_NaN();
  else if (text == "inf") value = std::numeric_limits<double>::infinity();
  else if (text == "-inf") value = -std::numeric_limits<double>::infinity();
  else return false;
  return true;
}

// Reads the one flat object straight into Metrics, whose index keeps
// 100,000 names fast; a document parsed whole into ordered_json would look
// each name up in a list. Anything but an object of numbers and nulls is
// refused, naming what was found.
class FlatObjectReader : public nlohmann::json_sax<nlohmann::json> {
 public:
  explicit FlatObjectReader(Metrics& metrics) : metrics_(metrics) {}

  bool null() override {
    if (!opened_ || inArray_) return refuse("null");
    metrics_.setNotMeasured(name_);
    return true;
  }
  bool number_integer(number_integer_t number) override { return metric(static_cast<double>(number)); }
  bool number_unsigned(number_unsigned_t number) override { return metric(static_cast<double>(number)); }
  bool number_float(number_float_t number, const string_t&) override { return metric(number); }
  bool boolean(bool) override { return refuse("a boolean"); }
  bool string(string_t& text) override {
    double nonFinite = 0.0;
    if (!inArray_) return nonFiniteFromText(text, nonFinite) ? metric(nonFinite) : refuse("a string");
    texts_.push_back(text);
    return true;
  }
  bool binary(binary_t&) override { return refuse("binary data"); }
  // Only an array of strings, in the object (a list of sentences).
  bool start_array(std::size_t) override {
    if (!opened_ || inArray_) return refuse("an array");
    inArray_ = true;
    texts_.clear();
    return true;
  }
  bool end_array() override {
    inArray_ = false;
    metrics_.setTexts(name_, texts_);
    return true;
  }
  bool start_object(std::size_t) override {
    if (opened_) return refuse("an object");
    opened_ = true;
    return true;
  }
  bool key(string_t& name) override {
    name_ = name;
    return true;
  }
  bool end_object() override { return true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::json::exception& error) override {
    // nlohmann's text without its "[json.exception.parse_error.101] " tag:
    // "parse error at line 2, column 9: syntax error while parsing value - ...".
    const std::string what = error.what();
    const size_t tag = what.find("] ");
    throw std::runtime_error("metrics JSON: " + (tag == std::string::npos ? what : what.substr(tag + 2)));
  }

 private:
  bool metric(double value) {
    if (!opened_) return refuse("a number");
    if (inArray_) return refuse("an array with a number");
    metrics_.set(name_, value);
    return true;
  }
  [[noreturn]] bool refuse(const char* found) {
    if (!opened_) throw std::runtime_error(std::string("metrics JSON: expected an object, found ") + found);
    throw std::runtime_error("metrics JSON: \"" + name_ + "\" is " + found +
                             ", not a number, null, \"nan\", \"inf\", \"-inf\" or list of strings");
  }

  Metrics& metrics_;
  bool opened_ = false;  // the one object has begun
  bool inArray_ = false;
  std::vector<std::string> texts_;
  std::string name_;     // the name of the value being read
};
}  // namespace

void Metrics::print(std::ostream& out) const {
  for (size_t i = 0; i < entries_.size(); ++i)
    out << entries_[i].first << " = " << (notMeasured_[i] ? NOT_MEASURED_TEXT : formatNumber(entries_[i].second))
        << '\n';
  for (const auto& [name, texts] : texts_)
    for (const std::string& text : texts) out << name << ": " << text << '\n';
}

std::string Metrics::toJson() const {
  // One name a line, indented by two. nlohmann writes each name as a JSON
  // string (quotes and backslashes escaped; a name that is not UTF-8 with
  // U+FFFD rather than spoiling the file).
  std::string json = "{";
  for (size_t i = 0; i < entries_.size(); ++i) {
    const std::string name =
        nlohmann::json(entries_[i].first).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    json += (i ? ",\n  " : "\n  ") + name + ": " + (notMeasured_[i] ? NOT_MEASURED_JSON : jsonNumber(entries_[i].second));
  }
  for (size_t i = 0; i < texts_.size(); ++i) {
    const nlohmann::json name(texts_[i].first), list(texts_[i].second);
    json += (entries_.empty() && i == 0 ? "\n  " : ",\n  ") +
            name.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + ": " +
            list.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  }
  json += "\n}\n";
  return json;
}

void Metrics::writeJsonAtomically(const std::string& path) const { writeFileAtomically(path, toJson()); }

Metrics parseMetricsJson(const std::string& text) {
  Metrics metrics;
  FlatObjectReader reader(metrics);
  nlohmann::json::sax_parse(text, &reader);
  return metrics;
}

}  // namespace odelab
