#include "JsonLines.h"

#include <cctype>
#include <cstring>
#include <map>

namespace odelab::world {

namespace {

// Records the line of every value's start, keyed by its path.
class LineWalker {
 public:
  explicit LineWalker(const std::string& text) : text_(text) {}

  std::map<std::string, int> walk() {
    skipSpace();
    value("");
    return lines_;
  }

 private:
  void skipSpace() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) {
      if (text_[at_] == '\n') ++line_;
      ++at_;
    }
  }

  std::string string() {  // at the opening quote; returns the raw contents
    std::string out;
    for (++at_; at_ < text_.size() && text_[at_] != '"'; ++at_) {
      if (text_[at_] == '\\') out += text_[at_++];
      out += text_[at_];
    }
    ++at_;
    return out;
  }

  void value(const std::string& path) {
    lines_.emplace(path, line_);
    if (at_ >= text_.size()) return;
    const char c = text_[at_];
    if (c == '{') {
      ++at_;
      for (skipSpace(); at_ < text_.size() && text_[at_] != '}'; skipSpace()) {
        if (text_[at_] == ',') {
          ++at_;
          continue;
        }
        const std::string key = string();
        skipSpace();
        ++at_;  // ':'
        skipSpace();
        value(path.empty() ? key : path + "." + key);
      }
      ++at_;
    } else if (c == '[') {
      ++at_;
      int index = 0;
      for (skipSpace(); at_ < text_.size() && text_[at_] != ']'; skipSpace()) {
        if (text_[at_] == ',') {
          ++at_;
          continue;
        }
        value(path + "[" + std::to_string(index++) + "]");
      }
      ++at_;
    } else if (c == '"') {
      string();
    } else {
      while (at_ < text_.size() && !std::strchr(",]} \t\r\n", text_[at_])) ++at_;
    }
  }

  const std::string& text_;
  std::size_t at_ = 0;
  int line_ = 1;
  std::map<std::string, int> lines_;
};

}  // namespace

int lineOfPath(const std::string& text, const std::string& wanted) {
  std::string path = wanted;
  const std::map<std::string, int> lines = LineWalker(text).walk();
  for (;;) {
    const auto found = lines.find(path);
    if (found != lines.end()) return found->second;
    const std::size_t cut = path.find_last_of(".[");
    if (cut == std::string::npos) return path.empty() ? 0 : lines.at("");
    path.resize(cut);
  }
}

}  // namespace odelab::world
