#include "EventScript.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <sstream>

#include "CommandLine.h"
#include "SafeFile.h"

namespace odelab {

namespace {

// Splits a line into words at blanks; "a quoted word" keeps its blanks.
// A '#' outside quotes starts a comment. Returns false on an unclosed quote.
bool splitWords(const std::string& line, std::vector<std::string>& words) {
  words.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    const char c = line[i];
    if (c == '#') break;
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
      continue;
    }
    std::string word;
    if (c == '"') {
      const std::size_t end = line.find('"', i + 1);
      if (end == std::string::npos) return false;
      word = line.substr(i + 1, end - i - 1);
      i = end + 1;
    } else {
      while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i])) && line[i] != '#') word += line[i++];
    }
    words.push_back(word);
  }
  return true;
}

bool parseInteger(const std::string& text, long long min, long long max, long long& value) {
  if (text.empty()) return false;
  for (std::size_t i = 0; i < text.size(); ++i)
    if (!std::isdigit(static_cast<unsigned char>(text[i])) && !(i == 0 && text[i] == '-')) return false;
  errno = 0;
  char* end = nullptr;
  const long long parsed = std::strtoll(text.c_str(), &end, 10);
  if (errno != 0 || *end != '\0' || parsed < min || parsed > max) return false;
  value = parsed;
  return true;
}

bool isLabel(const std::string& text) {
  return !text.empty() && text.size() <= 64 &&
         std::all_of(text.begin(), text.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

// Reads words[2] and words[3] into event.x and event.y, each within
// [min, max]; calls `fail` (which throws) otherwise.
template <typename Fail>
void parsePair(const std::vector<std::string>& words, long long min, long long max, ScriptEvent& event, Fail fail) {
  long long x = 0, y = 0;
  if (!parseInteger(words[2], min, max, x) || !parseInteger(words[3], min, max, y)) fail();
  event.x = static_cast<int>(x);
  event.y = static_cast<int>(y);
}

}  // namespace

// std::getline with a bound: a line without an end (/dev/zero, a binary
// file) is refused, not read into memory. False at the end of the input.
static bool readBoundedLine(std::istream& in, std::string& text, bool& tooLong) {
  text.clear();
  tooLong = false;
  int c;
  while ((c = in.get()) != std::char_traits<char>::eof()) {
    if (c == '\n') return true;
    if (text.size() >= MAX_SCRIPT_LINE) {
      tooLong = true;
      return true;
    }
    text += static_cast<char>(c);
  }
  return !text.empty();
}

std::vector<ScriptEvent> parseEventScript(std::istream& in, const std::string& fileName, const KeyLookup& keyLookup) {
  std::vector<ScriptEvent> events;
  std::string text;
  std::vector<std::string> words;
  int lineNumber = 0;
  bool tooLong = false;
  while (readBoundedLine(in, text, tooLong)) {
    ++lineNumber;
    auto fail = [&](const std::string& what) {
      throw UsageError("--events: " + fileName + ":" + std::to_string(lineNumber) + ": " + what);
    };
    if (tooLong) fail("line longer than " + std::to_string(MAX_SCRIPT_LINE) + " characters");
    if (!text.empty() && text.back() == '\r') text.pop_back();
    if (!splitWords(text, words)) fail("unclosed quote");
    if (words.empty()) continue;
    if (words.size() < 2) fail("expected '<frame> <event> ...', found '" + words[0] + "'");

    ScriptEvent event;
    event.line = lineNumber;
    if (!parseInteger(words[0], 1, MAX_EVENT_FRAME, event.frame))
      fail("frame '" + words[0] + "' is not a whole number from 1 to " + std::to_string(MAX_EVENT_FRAME));
    const std::string& verb = words[1];
    const auto failPixels = [&] { fail(verb + ": x and y are window pixels, whole numbers from 0 (top left) to 100000"); };
    int repeat = 1;
    if (verb == "key") {
      event.kind = ScriptEvent::Kind::Key;
      if (words.size() < 3) fail("key: expected '<frame> key <name> [shift] [ctrl] [alt] [*N]'");
      event.keyName = words[2];
      event.key = keyLookup(event.keyName);
      if (event.key == 0) fail("key: unknown key name '" + event.keyName + "' (names as SDL_GetKeyFromName: P, F3, \",\", Escape)");
      for (std::size_t i = 3; i < words.size(); ++i) {
        const std::string& option = words[i];
        long long count = 0;
        bool* modifier = option == "shift" ? &event.shift
                         : option == "ctrl" ? &event.ctrl
                         : option == "alt"  ? &event.alt
                                            : nullptr;
        if (modifier && !*modifier) {
          *modifier = true;
        } else if (option.size() > 1 && option[0] == '*' && parseInteger(option.substr(1), 1, MAX_EVENT_REPEAT, count)) {
          repeat = static_cast<int>(count);
        } else {
          fail("key: unexpected '" + option + "' (allowed after the name, each once: shift, ctrl, alt, *N with N from 1 to " +
               std::to_string(MAX_EVENT_REPEAT) + ")");
        }
      }
    } else if (verb == "down" || verb == "up") {
      event.kind = verb == "down" ? ScriptEvent::Kind::Down : ScriptEvent::Kind::Up;
      if (words.size() != 4 && words.size() != 5) fail(verb + ": expected '<frame> " + verb + " <x> <y> [left|middle|right]'");
      parsePair(words, 0, 100000, event, failPixels);
      if (words.size() == 5) {
        const std::string& name = words[4];
        if (name == "left")
          event.button = ScriptEvent::Button::Left;
        else if (name == "middle")
          event.button = ScriptEvent::Button::Middle;
        else if (name == "right")
          event.button = ScriptEvent::Button::Right;
        else
          fail(verb + ": unknown button '" + name + "' (left, middle, right)");
      }
    } else if (verb == "move") {
      event.kind = ScriptEvent::Kind::Move;
      if (words.size() != 4) fail("move: expected '<frame> move <x> <y>'");
      parsePair(words, 0, 100000, event, failPixels);
    } else if (verb == "wheel") {
      event.kind = ScriptEvent::Kind::Wheel;
      if (words.size() != 4) fail("wheel: expected '<frame> wheel <dx> <dy>'");
      parsePair(words, -MAX_WHEEL_NOTCHES, MAX_WHEEL_NOTCHES, event, [&] {
        fail("wheel: dx and dy are notches, whole numbers from -" + std::to_string(MAX_WHEEL_NOTCHES) + " to " +
             std::to_string(MAX_WHEEL_NOTCHES));
      });
    } else if (verb == "resize") {
      event.kind = ScriptEvent::Kind::Resize;
      if (words.size() != 4) fail("resize: expected '<frame> resize <width> <height>'");
      parsePair(words, 1, MAX_WINDOW_SIDE, event, [&] {
        fail("resize: width and height are pixels, whole numbers from 1 to " + std::to_string(MAX_WINDOW_SIDE));
      });
    } else if (verb == "mark") {
      event.kind = ScriptEvent::Kind::Mark;
      if (words.size() != 3 || !isLabel(words[2]))
        fail("mark: expected '<frame> mark <label>', the label made of letters, digits and _ (at most 64)");
      event.label = words[2];
    } else if (verb == "text") {
      event.kind = ScriptEvent::Kind::Text;
      // SDL carries typed text in events of at most 31 bytes.
      if (words.size() != 3 || words[2].size() > 31) fail("text: expected '<frame> text <characters>', at most 31, no spaces");
      event.label = words[2];
    } else if (verb == "quit") {
      event.kind = ScriptEvent::Kind::Quit;
      if (words.size() != 2) fail("quit: expected '<frame> quit'");
    } else {
      fail("unknown event '" + verb + "' (key, down, move, up, wheel, resize, mark, quit, text)");
    }
    if (events.size() + static_cast<std::size_t>(repeat) > MAX_SCRIPT_EVENTS)
      fail("more than " + std::to_string(MAX_SCRIPT_EVENTS) + " events in the script (repeats counted)");
    for (int i = 0; i < repeat; ++i) events.push_back(event);
  }
  if (in.bad()) throw UsageError("--events: cannot read " + fileName);
  std::stable_sort(events.begin(), events.end(),
                   [](const ScriptEvent& a, const ScriptEvent& b) { return a.frame < b.frame; });
  // One frame's events are queued at once: refused here, before a window
  // opens, rather than failing mid-session with "event queue is full".
  for (std::size_t first = 0, i = 0; i <= events.size(); ++i) {
    if (i < events.size() && events[i].frame == events[first].frame) continue;
    if (i - first > MAX_EVENTS_PER_FRAME)
      throw UsageError("--events: " + fileName + ":" + std::to_string(events[first].line) + ": frame " +
                       std::to_string(events[first].frame) + " has " + std::to_string(i - first) +
                       " events (repeats counted); at most " + std::to_string(MAX_EVENTS_PER_FRAME) +
                       " fit SDL's event queue in one frame");
    first = i;
  }
  return events;
}

std::vector<ScriptEvent> loadEventScript(const std::string& path, const KeyLookup& keyLookup) {
  // A FIFO would block and /dev/zero never ends: the one bounded reader.
  std::istringstream file;
  try {
    file.str(readBoundedFile(path, MAX_SCRIPT_BYTES, "the script"));
  } catch (const ReadRefused& error) {
    throw UsageError(std::string("--events: ") + error.what());
  }
  return parseEventScript(file, path, keyLookup);
}

}  // namespace odelab
