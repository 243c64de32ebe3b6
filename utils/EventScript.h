#pragma once

#include <cstddef>
#include <functional>
#include <istream>
#include <string>
#include <vector>

namespace odelab {

// Scripted input for a window run (--events FILE): one event a line, played
// before the given frame's event polling. The format (doc/manual.md,
// "Scripted input"):
//
//   # a comment; blank lines are ignored, and so is text after '#'
//   <frame> key <name> [shift] [ctrl] [alt] [*N]   press and release a key (N times)
//   <frame> down <x> <y> [left|middle|right]       mouse button down at window pixel (x, y)
//   <frame> move <x> <y>                           mouse moves to (x, y)
//   <frame> up <x> <y> [left|middle|right]         mouse button up at (x, y)
//   <frame> wheel <dx> <dy>                        wheel turned (notches; dy > 0 away from the user)
//   <frame> resize <width> <height>                the window resized (SDL_SetWindowSize)
//   <frame> mark <label>                           record metrics mark_<label>_steps, _sim_seconds, _hash
//   <frame> quit                                   close the window, as the user would
//   <frame> text <characters>                      type characters into the focused field (no spaces)
//
// Frames count from 1 (the first frame). Events of one frame run in the
// order of the file; lines need not be in frame order. Key names are SDL's
// (SDL_GetKeyFromName: "P", "F3", ",", "Escape"; one with a space is quoted:
// "Left Shift"), case-insensitive.
struct ScriptEvent {
  enum class Kind { Key, Down, Move, Up, Wheel, Resize, Mark, Quit, Text };
  enum class Button { Left, Middle, Right };
  long long frame = 1;
  Kind kind = Kind::Key;
  int key = 0;             // Key: the key code
  std::string keyName;     // Key: as written
  bool shift = false;      // Key: with Shift held
  bool ctrl = false;       // Key: with Ctrl held
  bool alt = false;        // Key: with Alt held
  Button button = Button::Left;  // Down, Up
  // Down, Move, Up: window pixels from the top-left corner. Wheel: notches
  // right (x) and away from the user (y). Resize: the new size in pixels.
  int x = 0, y = 0;
  std::string label;       // Mark: the label; Text: the characters typed
  int line = 0;            // where it was written, for messages
};

// Turns a key name into a key code, 0 when the name is unknown. The window
// passes SDL_GetKeyFromName; the parser itself needs no SDL library.
using KeyLookup = std::function<int(const std::string& name)>;

// The largest repeat count (*N) and frame number accepted.
constexpr int MAX_EVENT_REPEAT = 100000;
constexpr long long MAX_EVENT_FRAME = 1000000000LL;
// Bounds that keep a script's memory and SDL's event queue (65,535 events;
// a script event queues at most two) within reach: events in all (repeats
// counted), events in one frame, characters in a line, bytes in the file.
constexpr std::size_t MAX_SCRIPT_EVENTS = 200000;
constexpr std::size_t MAX_EVENTS_PER_FRAME = 16384;
constexpr std::size_t MAX_SCRIPT_LINE = 1024;
constexpr long long MAX_SCRIPT_BYTES = 8LL << 20;
// The largest wheel turn (notches) and window size (pixels) accepted.
constexpr int MAX_WHEEL_NOTCHES = 100;
constexpr int MAX_WINDOW_SIDE = 8192;

// Parses a script; events come back sorted by frame, file order kept within
// a frame, repeats expanded. Throws UsageError (CommandLine.h) naming
// `fileName`, the line and what is wrong.
std::vector<ScriptEvent> parseEventScript(std::istream& in, const std::string& fileName, const KeyLookup& keyLookup);
// Reads and parses FILE, a regular file of at most MAX_SCRIPT_BYTES (not a
// FIFO or /dev/zero); throws UsageError when it cannot be read.
std::vector<ScriptEvent> loadEventScript(const std::string& path, const KeyLookup& keyLookup);

}  // namespace odelab
