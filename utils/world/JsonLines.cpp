#include "JsonLines.h"

#include <algorithm>
#include <cstdlib>
#include <string_view>
#include <vector>

namespace odelab::world {

namespace {

// One step of a path: an object's key (as written, escapes and all) or an
// array's index. A view into the text or the path: the walk copies no key
// (a copy per key and a "[i]" per item were a third of reading a large world).
struct Step {
  std::string_view key;
  long index = -1;  // >= 0: an array's item
  bool operator==(const Step& other) const { return index == other.index && key == other.key; }
  std::string text() const { return index < 0 ? std::string(key) : "[" + std::to_string(index) + "]"; }
};

// "bodies[1].position" as its steps: "bodies", [1], "position".
std::vector<Step> pathSteps(const std::string& path) {
  std::vector<Step> steps;
  std::size_t key = 0;  // where the key being read starts
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (path[i] == '.' || path[i] == '[') {
      if (i > key) steps.push_back({std::string_view(path).substr(key, i - key)});
      key = i + 1;
      if (path[i] == '[') {
        const std::size_t close = path.find(']', i);
        if (close == std::string::npos) return steps;
        steps.push_back({{}, std::strtol(path.c_str() + i + 1, nullptr, 10)});
        i = close;
        key = i + 1;
      }
    }
  }
  if (path.size() > key) steps.push_back({std::string_view(path).substr(key)});
  return steps;
}

// One pass over the text. Lenient: text nlohmann refuses ends the walk where
// its shape stops making sense, and nlohmann's own message is then the one said.
class Walker {
 public:
  Walker(const std::string& text, std::vector<Step> wanted)
      : text_(text), wanted_(std::move(wanted)), lines_(wanted_.size() + 1, 0) {}

  void walk() {
    if (text_.compare(0, 3, "\xEF\xBB\xBF") == 0) at_ = 3;
    skipSpace();
    value();
  }
  const JsonShape& shape() const { return shape_; }
  // The line of the deepest step of the wanted path found, 0 for none.
  int wantedLine() const {
    for (std::size_t k = lines_.size(); k-- > 0;)
      if (lines_[k]) return lines_[k];
    return 0;
  }

 private:
  bool atEnd() const { return at_ >= text_.size(); }

  static bool space(char c) { return c == ' ' || c == '\n' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
  static bool endsScalar(char c) { return space(c) || c == ',' || c == ']' || c == '}' || c == ':' || c == '\0'; }

  void skipSpace() {
    while (!atEnd() && space(text_[at_])) {
      if (text_[at_] == '\n') ++line_;
      ++at_;
    }
  }

  std::string_view string() {  // at the opening quote; returns the raw contents (escapes as written)
    const std::size_t start = ++at_;
    while (!atEnd() && text_[at_] != '"') {
      if (text_[at_] == '\n') ++line_;
      at_ += text_[at_] == '\\' && at_ + 1 < text_.size() ? 2 : 1;
    }
    const std::size_t end = std::min(at_, text_.size());
    ++at_;
    return std::string_view(text_).substr(start, end - start);
  }

  std::string pathText(const Step& last) const {
    std::string path;
    for (const Step& step : steps_) path += (path.empty() || step.index >= 0 ? "" : ".") + step.text();
    return path + (path.empty() || last.index >= 0 ? "" : ".") + last.text();
  }

  void push(const Step& step) {
    if (matched_ == steps_.size() && matched_ < wanted_.size() && wanted_[matched_] == step) ++matched_;
    steps_.push_back(step);
  }
  void pop() {
    steps_.pop_back();
    if (matched_ > steps_.size()) matched_ = steps_.size();
  }

  void value() {
    if (matched_ == steps_.size() && !lines_[matched_]) lines_[matched_] = line_;
    if (atEnd()) return;
    const char c = text_[at_];
    if (c == '{' || c == '[') {
      container(c);
    } else if (c == '"') {
      string();
    } else {
      while (!atEnd() && !endsScalar(text_[at_])) ++at_;
    }
  }

  void container(char open) {
    if (depth_ >= MAX_JSON_DEPTH) {
      shape_.tooDeepLine = line_;
      stopped_ = true;
      return;
    }
    const char close = open == '{' ? '}' : ']';
    ++at_;
    ++depth_;
    // The object's keys with their lines, on one stack shared by every open
    // object (no allocation per object), sorted at its end to find one given twice.
    const std::size_t firstKey = keys_.size();
    long index = 0;
    skipSpace();
    if (!atEnd() && text_[at_] == close) {
      ++at_;
      --depth_;
      return;
    }
    struct Closing {  // on every way out: the keys looked at while steps_ is still this object's path
      Walker& walker;
      std::size_t firstKey;
      ~Closing() { walker.duplicates(firstKey); }
    } closing{*this, firstKey};
    while (!stopped_) {
      const std::size_t start = at_;
      Step step;
      if (open == '{') {
        if (atEnd() || text_[at_] != '"') return stop();
        const int keyLine = line_;
        step.key = string();
        keys_.emplace_back(step.key, keyLine);
        skipSpace();
        if (atEnd() || text_[at_] != ':') return stop();
        ++at_;
        skipSpace();
      } else {
        step.index = index++;
      }
      push(step);
      value();
      pop();
      if (stopped_) return;
      const std::size_t end = at_;
      const int endLine = line_;
      skipSpace();
      if (atEnd()) return stop();
      if (text_[at_] == ',') {
        ++at_;
        skipSpace();
        continue;
      }
      if (text_[at_] == close) {
        ++at_;
        --depth_;
        return;
      }
      if (!shape_.missingLine) missing(start, end, endLine, close);
      return stop();
    }
  }

  // The keys of the object that ends, keys_ from `first` on, are looked at and let go.
  void duplicates(std::size_t first) {
    const auto begin = keys_.begin() + static_cast<std::ptrdiff_t>(first);
    if (keys_.size() - first >= 2 && !shape_.duplicateLine) {
      std::sort(begin, keys_.end());
      for (auto key = begin + 1; key != keys_.end(); ++key)
        if (key->first == (key - 1)->first) {
          shape_.duplicateLine = key->second;  // the second time it is given
          shape_.duplicatePath = pathText({key->first});
          break;
        }
    }
    keys_.erase(begin, keys_.end());
  }

  // The value from `start` to `end`, as a person would quote it: its first line, cut short.
  void missing(std::size_t start, std::size_t end, int endLine, char close) {
    std::string quoted = text_.substr(start, std::min<std::size_t>(end - start, 200));
    const std::size_t newline = quoted.find('\n');
    if (newline != std::string::npos || quoted.size() > 60) quoted = quoted.substr(0, std::min<std::size_t>(newline, 60)) + " ...";
    shape_.missingLine = endLine;
    shape_.missingAt = at_;
    shape_.missingAfter = quoted;
    shape_.missingCloser = close;
  }

  void stop() { stopped_ = true; }

  const std::string& text_;
  const std::vector<Step> wanted_;
  std::vector<int> lines_;  // per length k of the wanted path's prefix found: its line
  std::vector<Step> steps_;
  std::vector<std::pair<std::string_view, int>> keys_;  // the open objects' keys and their lines
  std::size_t matched_ = 0;  // how many of steps_ agree with wanted_
  std::size_t at_ = 0;
  int line_ = 1;
  int depth_ = 0;
  bool stopped_ = false;
  JsonShape shape_;
};

}  // namespace

JsonShape scanJsonShape(const std::string& text) {
  Walker walker(text, {});
  walker.walk();
  return walker.shape();
}

int lineOfPath(const std::string& text, const std::string& path) {
  Walker walker(text, pathSteps(path));  // its steps view `path`, which outlives the walk
  walker.walk();
  return walker.wantedLine();
}

}  // namespace odelab::world
