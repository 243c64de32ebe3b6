// Which reader a world file goes to: SDF (WorldFromSdf.h), MJCF
// (WorldFromMjcf.h) or this format's JSON (WorldJson.cpp). Every build, with
// the XML readers or without them, uses the same tests, so that an SDF or
// MJCF file is named as such either way.
#include <cstring>

#include "WorldFromMjcf.h"
#include "WorldFromSdf.h"

namespace odelab::world {

namespace {

bool endsWith(const std::string& path, const std::string& tail) {
  return path.size() >= tail.size() && path.compare(path.size() - tail.size(), tail.size(), tail) == 0;
}

// Where the first element starts: after blanks, an XML declaration and
// comments; npos when one of those is never closed.
size_t firstElement(const std::string& text) {
  size_t at = 0;
  while (true) {
    while (at < text.size() && text[at] && std::strchr(" \t\r\n", text[at])) ++at;
    const char* close = text.compare(at, 5, "<?xml") == 0 ? "?>" : text.compare(at, 4, "<!--") == 0 ? "-->" : nullptr;
    if (!close) return at;
    const size_t end = text.find(close, at);
    if (end == std::string::npos) return std::string::npos;
    at = end + std::strlen(close);
  }
}

bool startsWithElement(const std::string& text, const char* element) {
  const size_t at = firstElement(text);
  const size_t length = std::strlen(element);
  return at != std::string::npos && text.compare(at, length, element) == 0 &&
         (at + length == text.size() || std::strchr(" \t\r\n>/", text[at + length]));
}

}  // namespace

bool looksLikeMjcf(const std::string& path, const std::string& text) {
  return endsWith(path, ".xml") || startsWithElement(text, "<mujoco");
}

bool looksLikeSdf(const std::string& path, const std::string& text) {
  // An .xml file whose text is SDF is SDF: the text decides before the name.
  if (startsWithElement(text, "<sdf")) return true;
  return !startsWithElement(text, "<mujoco") && (endsWith(path, ".sdf") || endsWith(path, ".world"));
}

}  // namespace odelab::world
