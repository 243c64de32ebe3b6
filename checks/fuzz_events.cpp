// Writes a seeded random --events script for the window fuzz checks
// (issue 7): keys with and without modifiers, mouse motion, clicks of every
// button, wheel turns and window resizes, spread over frames, then a mark
// and Esc. The same seed gives the same script on every platform (the
// generator is splitmix64 and plain modulo, not the standard library's
// distributions, whose results differ between implementations).
//
//   fuzz_events --seed S [--events N] [--per-frame M] [--width W] [--height H] [--out FILE]
//
// The program given the script must take every event, reach the last mark
// (mark_fuzz_end_* in its metrics) and exit with status 0 on the final Esc.
#include <SDL2/SDL.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "check_cli.h"

namespace {

class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  // A whole number in [low, high]; the modulo bias is far below what matters here.
  int between(int low, int high) {
    return low + static_cast<int>(next() % static_cast<std::uint64_t>(high - low + 1));
  }
  bool chance(int percent) { return between(1, 100) <= percent; }

 private:
  std::uint64_t state_;
};

// Every key of SDL's default keymap whose name reads back as the same key
// (what the script's parser does), Escape left out: it ends the run, so it
// only comes last. `labKeys` are those ODE Lab binds somewhere: letters,
// digits, F1-F12, Space and the punctuation of the time keys.
struct KeyTable {
  std::vector<std::string> all, labKeys;
};

std::string scriptName(const char* name) {
  const std::string text(name);
  return text.find_first_of(" #") == std::string::npos ? text : "\"" + text + "\"";
}

KeyTable buildKeyTable() {
  KeyTable table;
  for (int scancode = 0; scancode < SDL_NUM_SCANCODES; ++scancode) {
    const SDL_Keycode key = SDL_GetKeyFromScancode(static_cast<SDL_Scancode>(scancode));
    if (key == SDLK_UNKNOWN || key == SDLK_ESCAPE) continue;
    const char* name = SDL_GetKeyName(key);
    if (!name || !*name || std::string(name).find('"') != std::string::npos) continue;
    if (SDL_GetKeyFromName(name) != key) continue;
    table.all.push_back(scriptName(name));
    const bool lab = (key >= SDLK_a && key <= SDLK_z) || (key >= SDLK_0 && key <= SDLK_9) ||
                     (key >= SDLK_F1 && key <= SDLK_F12) || key == SDLK_COMMA || key == SDLK_PERIOD ||
                     key == SDLK_MINUS || key == SDLK_EQUALS || key == SDLK_SPACE;
    if (lab) table.labKeys.push_back(scriptName(name));
  }
  return table;
}

struct Options {
  std::uint64_t seed = 0;
  int events = 10000;
  int perFrame = 10;
  int width = 960, height = 600;
  std::string out;
};

class ScriptWriter {
 public:
  ScriptWriter(const Options& options, const KeyTable& keys, std::ostream& out)
      : options_(options), keys_(keys), out_(out), random_(options.seed), width_(options.width),
        height_(options.height) {}

  void write() {
    out_ << "# fuzz_events --seed " << options_.seed << " --events " << options_.events << " --per-frame "
         << options_.perFrame << " --width " << options_.width << " --height " << options_.height << "\n";
    long long frame = 1;
    int written = 0;
    while (written < options_.events) {
      const int now = random_.between(0, 2 * options_.perFrame);
      for (int i = 0; i < now && written < options_.events; ++i) {
        writeEvent(frame);
        if (++written % 1000 == 0) out_ << frame << " mark fuzz_" << written << "\n";
      }
      ++frame;
    }
    // Esc closes what is open first (a panel field, the help) and asks once
    // when the settings changed, which random keys do: up to four presses,
    // a frame apart, end the run; the first that quits ends the script.
    out_ << frame << " mark fuzz_end\n";
    for (int press = 1; press <= 4; ++press) out_ << frame + press << " key Escape\n";
  }

 private:
  void writeEvent(long long frame) {
    const int kind = random_.between(1, 100);
    out_ << frame << ' ';
    if (kind <= 40) {
      writeKey();
    } else if (kind <= 75) {
      out_ << "move " << x() << ' ' << y();
    } else if (kind <= 91) {
      writeButton();
    } else if (kind <= 98) {
      out_ << "wheel " << random_.between(-2, 2) << ' ' << random_.between(-5, 5);
    } else {
      // A quarter of the resizes make the window tiny, down to one pixel.
      const bool tiny = random_.chance(25);
      width_ = tiny ? random_.between(1, 16) : random_.between(1, 1600);
      height_ = tiny ? random_.between(1, 16) : random_.between(1, 1000);
      out_ << "resize " << width_ << ' ' << height_;
    }
    out_ << '\n';
  }

  // About half the keys come from those ODE Lab binds, so that the settings,
  // view and scene keys are pressed often; half from the whole keyboard.
  // The keys that stop time (O, ',' and '.' pause, R starts over) are kept
  // rare and P, which resumes, more common, so that the scene runs for
  // about 40% of the frames with whatever settings the F-keys reached,
  // rather than sitting paused.
  void writeKey() {
    static const char* const TIME_KEYS[] = {"O", ",", ".", "R"};
    const int pick = random_.between(1, 1000);
    if (pick <= 30) {
      out_ << "key P";
    } else if (pick <= 50) {
      out_ << "key " << TIME_KEYS[random_.between(0, 3)];
    } else {
      const std::vector<std::string>& from = pick <= 520 ? keys_.labKeys : keys_.all;
      const std::string& name = from[static_cast<std::size_t>(random_.between(0, static_cast<int>(from.size()) - 1))];
      if (isTimeKey(name)) return writeKey();  // drawn by their own rates above
      out_ << "key " << name;
    }
    if (random_.chance(30)) {
      if (random_.chance(50)) out_ << " shift";
      if (random_.chance(50)) out_ << " ctrl";
      if (random_.chance(50)) out_ << " alt";
    }
  }

  static bool isTimeKey(const std::string& name) {
    return name == "P" || name == "O" || name == "," || name == "." || name == "R";
  }

  // Mostly the left button, and mostly a release of a held button next, so
  // that drags happen; but also releases with nothing held, and the middle
  // and right buttons.
  void writeButton() {
    static const char* const NAMES[] = {"left", "middle", "right"};
    const int button = random_.chance(60) ? 0 : random_.between(1, 2);
    const bool down = held_[button] ? random_.chance(20) : random_.chance(85);
    out_ << (down ? "down " : "up ") << x() << ' ' << y() << ' ' << NAMES[button];
    held_[button] = down;
  }

  // Positions fall inside the window, and a tenth of them beyond its right
  // and bottom edges.
  int x() { return random_.between(0, width_ + width_ / 10); }
  int y() { return random_.between(0, height_ + height_ / 10); }

  const Options& options_;
  const KeyTable& keys_;
  std::ostream& out_;
  SplitMix64 random_;
  int width_, height_;
  bool held_[3] = {false, false, false};
};

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{"Writes a seeded random --events script: keys, modifiers, mouse motion, clicks, wheel, resizes; "
               "then 'mark fuzz_end' and Esc.",
               "fuzz_events"};
  app.add_option("--seed", options.seed, "the generator's seed; the same seed gives the same script")->required();
  app.add_option("--events", options.events, "how many random events")->check(CLI::Range(1, 10000000));
  app.add_option("--per-frame", options.perFrame, "events per frame on average (0 to twice this each frame)")
      ->check(CLI::Range(1, 1000));
  app.add_option("--width", options.width, "the window's width at the start, in pixels")->check(CLI::Range(1, 8192));
  app.add_option("--height", options.height, "the window's height at the start, in pixels")->check(CLI::Range(1, 8192));
  app.add_option("--out", options.out, "write the script here rather than to standard output");
  if (auto status = checks::parse(app, argc, argv)) return *status;  // bad input: 2, as every check tool

  // SDL fills its keymap when the video subsystem starts; the dummy driver
  // needs no display.
  SDL_SetHint(SDL_HINT_VIDEODRIVER, "dummy");
  if (SDL_Init(SDL_INIT_VIDEO) != 0) {
    std::fprintf(stderr, "error: SDL's dummy video driver did not start: %s\n", SDL_GetError());
    return 1;
  }
  const KeyTable keys = buildKeyTable();
  SDL_Quit();
  if (keys.labKeys.empty() || keys.all.empty()) {
    std::fprintf(stderr, "error: SDL's default keymap gave no key names\n");
    return 1;
  }
  if (options.out.empty()) {
    ScriptWriter(options, keys, std::cout).write();
    return std::cout.good() ? 0 : 1;
  }
  // Written to a temporary name and renamed, so a failure leaves no half script.
  const std::string temporary = options.out + ".part";
  {
    std::ofstream file(temporary);
    if (file) ScriptWriter(options, keys, file).write();
    if (!file || !file.flush()) {
      std::fprintf(stderr, "error: cannot write %s\n", temporary.c_str());
      std::remove(temporary.c_str());
      return 1;
    }
  }
  if (std::rename(temporary.c_str(), options.out.c_str()) != 0) {
    std::fprintf(stderr, "error: cannot rename %s to %s\n", temporary.c_str(), options.out.c_str());
    std::remove(temporary.c_str());
    return 1;
  }
  return 0;
}
