#include "CommandLine.h"

#include "world/AtlasNotes.h"
#include "world/EngineCatalog.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "ExitCodes.h"
#include "MeasurementLog.h"
#include "Platform.h"
#include "SafeFile.h"

namespace odelab::cli {

namespace {

std::string formatNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

bool isWritableDirectory(const std::string& path) {
  struct stat info {};
  return stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode) && access(path.c_str(), W_OK) == 0;
}

#ifdef __EMSCRIPTEN__
// In the browser the options come from the page's address (web/scene.js
// turns "&erp=0.4" into "--erp 0.4"): there is no command line to add
// --help to, so the advice names the address parameter refused (the first
// option the message names) and the parameter that lists the options.
std::string usageAdvice(const std::string& message) {
  std::string advice;
  const auto dashes = message.find("--");
  if (dashes != std::string::npos) {
    const auto end = message.find_first_not_of(
        "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_", dashes + 2);
    const std::string name = message.substr(dashes + 2, end == std::string::npos ? end : end - dashes - 2);
    if (!name.empty()) advice = "The address parameter '" + name + "' was refused. ";
  }
  return advice +
         "Each option is an address parameter without its dashes (erp=0.4 for --erp 0.4, ccd for the flag "
         "--ccd); the address with help as its only option (scene.html?scene=testN&help) lists them.";
}
#else
std::string usageAdvice(const std::string&) { return "Run with --help for the options."; }
#endif

std::string fileName(const std::string& path) {
  const auto slash = path.find_last_of(platform::FOLDER_SEPARATORS);
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// A name --record gives a frame (FrameLoop::recordFrame): <program>_frame_
// then six or more digits, then .png; any program's, as the launcher's
// scenes each record under their own.
bool isRecordedFrameName(const std::string& path) {
  const std::string name = fileName(path), marker = "_frame_", ending = ".png";
  const auto at = name.rfind(marker);
  if (at == std::string::npos || at == 0 || name.size() < at + marker.size() + 6 + ending.size()) return false;
  if (name.compare(name.size() - ending.size(), ending.size(), ending) != 0) return false;
  const std::string digits = name.substr(at + marker.size(), name.size() - ending.size() - at - marker.size());
  return digits.find_first_not_of("0123456789") == std::string::npos;
}

}  // namespace

void requireAvailableEngine(const std::string& name, const std::string& option) {
  std::string names;
  for (const world::EngineInfo& engine : world::knownEngines()) {
    if (engine.name == name) {
      if (!engine.available) throw UsageError(option + " " + name + ": not available here: " + engine.missing);
      return;
    }
    names += (names.empty() ? "" : ", ") + engine.name;
  }
  throw UsageError(option + " " + name + ": no such engine; the engines are " + names + " (--list-engines)");
}

std::string enginesText() {
  std::ostringstream out;
  for (const world::EngineInfo& engine : world::knownEngines()) {
    out << engine.name << ": " << (engine.available ? "available" : "not available");
    if (!engine.version.empty()) out << ", version " << engine.version;
    if (!engine.precision.empty()) out << ", " << engine.precision;
    out << '\n';
    if (!engine.available) out << "  missing: " << engine.missing << '\n';
    if (!engine.bestSettings.empty()) out << "  best settings: " << engine.bestSettings << '\n';
    out << world::atlasNoteLines(engine.name);
  }
  if (*world::atlasNotesMade())
    out << "(measured: the accuracy atlas of " << world::atlasNotesMade()
        << ", doc/atlas-report/ATLAS.md; each case's answer is analytic, doc/atlas.md)\n";
  return out.str();
}

void requireReplaceableFile(const char* option, const std::string& file) {
  if (file.empty()) return;
  const std::string why = whyNotWritable(file);
  if (!why.empty())
    throw UsageError(std::string(option) + ": cannot write '" + file + "': " + why);
}

namespace {

// strtod, under CLI11's reading of a real number, takes "0x10" as 16; a
// person typing a setting means decimal.
bool isHexadecimal(const std::string& text) { return text.find_first_of("xX") != std::string::npos; }

}  // namespace

CLI::Validator finiteRange(double min, double max) {
  const std::string range = "[" + formatNumber(min) + ", " + formatNumber(max) + "]";
  return CLI::Validator(
      [min, max, range](std::string& text) -> std::string {
        double value = 0;
        if (isHexadecimal(text) || !CLI::detail::lexical_cast(text, value)) return "'" + text + "' is not a number";
        if (!std::isfinite(value)) return "'" + text + "' is not a finite number";
        if (value < min || value > max) return "'" + text + "' is outside " + range;
        return {};
      },
      "in " + range);
}

CLI::Validator decimalInteger() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        // CLI11 reads "010" as octal 8 and "0x10" as 16; a person typing a
        // count means decimal. Digits only, leading zeros dropped.
        size_t digits = (!text.empty() && (text[0] == '+' || text[0] == '-')) ? 1 : 0;
        if (digits == text.size()) return "'" + text + "' is not a decimal whole number";
        for (size_t i = digits; i < text.size(); ++i)
          if (text[i] < '0' || text[i] > '9') return "'" + text + "' is not a decimal whole number";
        const std::string sign = text.substr(0, digits) == "-" ? "-" : "";
        const size_t first = text.find_first_not_of('0', digits);
        text = first == std::string::npos ? "0" : sign + text.substr(first);
        return {};
      },
      "");
}

CLI::Validator integerRange(int min, int max) {
  const std::string range = "[" + std::to_string(min) + ", " + std::to_string(max) + "]";
  return CLI::Validator(
      [min, max, range](std::string& text) -> std::string {
        long long value = 0;
        if (!CLI::detail::lexical_cast(text, value)) return "'" + text + "' is not a whole number";
        if (value < min || value > max) return "'" + text + "' is outside " + range;
        return {};
      },
      "in " + range);
}

CLI::Validator positive(double max) {
  return CLI::Validator(
      [max](std::string& text) -> std::string {
        double value = 0;
        if (isHexadecimal(text) || !CLI::detail::lexical_cast(text, value)) return "'" + text + "' is not a number";
        if (!std::isfinite(value)) return "'" + text + "' is not a finite number";
        if (value <= 0 || value > max) return "'" + text + "' must be above 0 and at most " + formatNumber(max);
        return {};
      },
      "> 0");
}

void addCommonOptions(CLI::App& app, RunOptions& options) {
  app.add_flag("--headless", options.headless, "run with no window and no GL calls; print metrics and exit");
  app.add_option("--seconds", options.seconds,
                 "simulated seconds to run (headless default: the scene's; window: quit on the step a headless run ends on, default never)")
      ->check(positive(1e7));
  app.add_option("--seed", options.seed, "seed for every random choice of the scene and for ODE's dRandSetSeed")
      ->capture_default_str();
  app.add_option("--out-dir", options.outDir,
                 "folder for output files such as Test2_output.txt (a link, hard link or FIFO there is refused)")
      ->capture_default_str();
  app.add_option("--metrics-json", options.metricsJson,
                 "write the metrics as a flat JSON object to FILE (atomically: to a hidden temporary file "
                 "beside it, .FILE.XXXXXX, then renamed)");
  app.add_option("--screenshot", options.screenshot,
                 "window: render --frames frames, save a PNG to FILE, exit (with --seconds and no --frames: at the "
                 "run's end)");
  app.add_option("--frames", options.frames, "frames to render before --screenshot")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  app.add_option("--record", options.recordDir,
                 "window: save every frame as DIR/<test>_frame_000001.png ... (see doc/manual.md for a video); "
                 "--metrics-json and --screenshot may not name one");
  app.add_option("--events", options.eventsFile,
                 "window: play scripted input from FILE, a regular file of at most 8 MiB (see doc/manual.md, "
                 "\"Scripted input\")")
      ->check(CLI::ExistingFile);
  app.add_option("--shader-dir", options.shaderDir, "folder holding the GLSL shaders (see doc/manual.md)");
  app.add_option("--font", options.fontPath, "TTF font for the HUD (see doc/manual.md)");
  app.add_option("--width", options.width, "window width in pixels")->check(CLI::Range(64, 16384))->capture_default_str();
  app.add_option("--height", options.height, "window height in pixels")
      ->check(CLI::Range(64, 16384))
      ->capture_default_str();
  addWindowOptions(app, options);
}

void addWindowOptions(CLI::App& app, RunOptions& options) {
  app.add_option("--max-frame-time", options.maxFrameTime,
                 "window: most real time one frame may advance the simulation, s (the thesis's loop: 0.01)")
      ->check(finiteRange(1e-4, 10.0))
      ->capture_default_str();
  app.add_option("--max-fps", options.maxFps, "window: frame cap per second; 0: none")
      ->check(finiteRange(0.0, 1000.0))
      ->capture_default_str();
  app.add_flag("!--no-vsync", options.vsync, "window: do not wait for the display's refresh");
  app.add_option("--text-size", options.textSize, "window: text height of the HUD, the help and the panel in pixels; "
                 "0: a 45th of the window's height, 12 to 28")
      ->check(CLI::Range(0, 200))
      ->capture_default_str();
  app.add_option_function<std::string>(
         "--hud",
         [&options](const std::string& value) {
           options.hud = value == "full" ? HudMode::Full : value == "off" ? HudMode::Off : HudMode::Compact;
         },
         "window: HUD compact, full or off (F1 cycles)")
      ->check(CLI::IsMember({"compact", "full", "off"}))
      ->default_str("compact");
  app.add_flag("!--no-panel", options.panel, "window: start with the control panel hidden (Tab shows it)");
}

void addKnobOptions(CLI::App& app, std::deque<Knob>& knobs) {
  for (Knob& knob : knobs) {
    if (knob.option.empty()) continue;
    Knob* target = &knob;
    if (knob.kind == KnobKind::Switch) {  // a flag: given, it turns the switch on ("--ccd=false" too is read)
      knob.parsed = app.add_flag(knob.option, *knob.on, knob.help);
      continue;
    }
    const std::string range = knob.rangeText();
    CLI::Option* option = app.add_option_function<std::string>(
        knob.option, [target](const std::string& text) { target->set(target->parse(text)); }, knob.help);
    option->type_name(knob.kind == KnobKind::Choice ? "TEXT" : knob.kind == KnobKind::Integer ? "INT" : "FLOAT");
    option->default_str(knob.optionText());
    option->check(CLI::Validator(
        [target, range](std::string& text) -> std::string {
          if (target->kind == KnobKind::Choice)
            return std::isnan(target->parse(text)) ? "'" + text + "' is not " + range : std::string();
          const double value = target->parse(text);
          // inf only where the knob's range reaches it (mu, test5's max correcting velocity).
          if (std::isnan(value)) {
            double any = 0;
            return "'" + text + "' is not a " +
                   (CLI::detail::lexical_cast(text, any) && !isHexadecimal(text) ? "finite number" : "number");
          }
          if (!target->accepts(value))
            return "'" + text + "' is outside " + range +
                   (target->kind == KnobKind::Integer ? " or not a whole number" : "");
          return {};
        },
        knob.kind == KnobKind::Choice ? range : "in " + range));
    if (knob.kind == KnobKind::Integer) option->transform(decimalInteger());
    knob.parsed = option;
  }
}

void checkKnobs(const CLI::App& app, const std::deque<Knob>& knobs, double step) {
  for (const Knob& knob : knobs) {
    if (!knob.parsed || knob.parsed->count() == 0) continue;
    if (!knob.companion.empty() && app.count(knob.companion) == 0)
      throw UsageError(knob.option + ": only used with " + knob.companion);
    if (knob.kind == KnobKind::Interval && !(knob.offAtZero && knob.get() == 0))
      refuseBelowStep(knob.option.c_str(), knob.get(), step);
  }
}

std::string settingsJson(const std::deque<Knob>& knobs) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  // JSON has no infinity: a range reaching it says "inf", as the option takes it.
  const auto number = [](double v) -> nlohmann::ordered_json {
    if (std::isinf(v)) return "inf";
    return v;
  };
  const char* groups[] = {"world", "contacts", "scene"};
  for (const Knob& knob : knobs) {
    nlohmann::ordered_json entry;
    entry["name"] = knob.name;
    entry["option"] = knob.option;
    entry["key"] = knob.keyName;
    if (knob.kind == KnobKind::Switch) {
      entry["default"] = knob.get() > 0;
      entry["kind"] = "switch";
    } else if (knob.kind == KnobKind::Choice) {
      entry["choices"] = knob.choices;
      entry["default"] = knob.words();
      entry["kind"] = "choice";
    } else {
      const bool whole = knob.kind == KnobKind::Integer;
      entry["min"] = whole ? nlohmann::ordered_json(static_cast<long long>(knob.min)) : number(knob.min);
      entry["max"] = whole ? nlohmann::ordered_json(static_cast<long long>(knob.max)) : number(knob.max);
      entry["default"] = knob.kind == KnobKind::Integer ? nlohmann::ordered_json(static_cast<long long>(knob.get()))
                                                         : number(knob.get());
      entry["kind"] = knob.kind == KnobKind::Integer ? "integer" : knob.kind == KnobKind::Interval ? "interval" : "real";
    }
    entry["unit"] = knob.unit;
    entry["group"] = groups[static_cast<int>(knob.group)];
    entry["header"] = knob.headerKey();
    entry["metric"] = "knob_" + knob.name;
    entry["off_at_zero"] = knob.offAtZero;
    entry["only_with"] = knob.companion;
    entry["scene_default"] = knob.sceneDefault;
    list.push_back(std::move(entry));
  }
  return list.dump(2) + "\n";
}

void rejectEmptyValues(CLI::App& app) {
  const CLI::Validator nonEmpty(
      [](std::string& text) -> std::string { return text.empty() ? "an empty value is not allowed" : ""; }, "");
  for (CLI::Option* option : app.get_options())
    if (option->get_type_size() > 0) option->check(nonEmpty);
  // Whole-number options (the scenes' counts too) read decimal only.
  for (CLI::Option* option : app.get_options()) {
    // The type name carries the validators' descriptions: "INT:INT in [1 - 10]".
    const std::string type = option->get_type_name();
    const std::string base = type.substr(0, type.find(':'));
    if (base == "INT" || base == "UINT") option->transform(decimalInteger());
  }
}

void refuseOwnOutputs(const RunOptions& options, const std::vector<std::string>& outputNames) {
  for (const std::string& name : outputNames) {
    const std::string output = joinPath(options.outDir, name);
    if (!options.metricsJson.empty() && sameFilePath(options.metricsJson, output))
      throw UsageError("--metrics-json: '" + options.metricsJson + "' is this program's own output file '" + output +
                       "' (a scene this session can open writes it); name another file");
    if (!options.screenshot.empty() && sameFilePath(options.screenshot, output))
      throw UsageError("--screenshot: '" + options.screenshot + "' is this program's own output file '" + output +
                       "' (a scene this session can open writes it); name another file");
  }
  if (!options.metricsJson.empty() && sameFilePath(options.metricsJson, options.screenshot))
    throw UsageError("--metrics-json: '" + options.metricsJson + "' is also the --screenshot file");
  if (options.recordDir.empty()) return;
  for (const auto& [option, file] : {std::pair{"--metrics-json", options.metricsJson}, {"--screenshot", options.screenshot}})
    if (!file.empty() && isRecordedFrameName(file) && sameFilePath(file, joinPath(options.recordDir, fileName(file))))
      throw UsageError(std::string(option) + ": '" + file + "' is a frame --record saves in '" + options.recordDir +
                       "'; name another file");
}

void refuseUnwritableOutputs(const RunOptions& options, const std::vector<std::string>& outputNames) {
  for (const std::string& name : outputNames) {
    const std::string output = joinPath(options.outDir, name);
    const std::string why = whyNotWritable(output);
    if (!why.empty())
      throw UsageError("cannot write '" + output + "': " + why);
  }
}

void refuseInputsAsOutputs(const RunOptions& options, const std::vector<std::string>& outputNames,
                           const std::vector<std::pair<std::string, std::string>>& inputs,
                           const std::string& exportWorld) {
  std::vector<std::pair<std::string, std::string>> read = inputs;
  if (!options.eventsFile.empty()) read.emplace_back("--events", options.eventsFile);
  if (!options.fontPath.empty()) read.emplace_back("--font", options.fontPath);
  std::vector<std::pair<std::string, std::string>> written{
      {"--metrics-json", options.metricsJson}, {"--screenshot", options.screenshot}, {"--export-world", exportWorld}};
  for (const std::string& name : outputNames) written.emplace_back("--out-dir", joinPath(options.outDir, name));
  for (const auto& [inputOption, input] : read) {
    for (const auto& [outputOption, output] : written)
      if (sameFile(input, output))
        throw UsageError(outputOption + ": '" + output + "' is the file " + inputOption + " reads ('" + input +
                         "'); a run never writes what it reads: name another file");
    if (!options.recordDir.empty() && isRecordedFrameName(input) &&
        sameFile(input, joinPath(options.recordDir, fileName(input))))
      throw UsageError("--record: '" + input + "', which " + inputOption + " reads, is a frame --record saves in '" +
                       options.recordDir + "'; name another folder");
  }
}

void refuseBelowStep(const char* option, double interval, double step) {
  if (interval < step)
    throw UsageError(std::string(option) + ": " + formatNumber(interval) + " s is below one step (--step " +
                     formatNumber(step) + " s)");
}

void refuseRunShorterThanStep(const RunOptions& options, double step) {
  refuseRunShorterThanStep(options.seconds, step);
}

void refuseRunShorterThanStep(double seconds, double step) {
  // llround(seconds / step) would be 0 steps, a run that measured nothing.
  if (seconds > 0 && seconds < step)
    throw UsageError("--seconds: " + formatNumber(seconds) + " s is less than one step (--step " +
                     formatNumber(step) + " s); the run would take no step");
}

std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv, const std::function<void()>& checks) {
  try {
    app.parse(argc, argv);
    checks();
  } catch (const CLI::Success& done) {  // --help, --version
    return app.exit(done);
  } catch (const CLI::ParseError& error) {
    std::cerr << "error: " << error.what() << "\n" << usageAdvice(error.what()) << "\n";
    return exit_code::USAGE;
  } catch (const UsageError& error) {
    std::cerr << "error: " << error.what() << "\n" << usageAdvice(error.what()) << "\n";
    return exit_code::USAGE;
  }
  return std::nullopt;
}

void validateRunOptions(const RunOptions& options) {
  if (!isWritableDirectory(options.outDir))
    throw UsageError("--out-dir: '" + options.outDir + "' does not exist or is not a writable folder");
  requireReplaceableFile("--metrics-json", options.metricsJson);
  requireReplaceableFile("--screenshot", options.screenshot);
  if (!options.recordDir.empty() && !isWritableDirectory(options.recordDir))
    throw UsageError("--record: '" + options.recordDir + "' does not exist or is not a writable folder");
  if (options.headless && !options.recordDir.empty())
    throw UsageError("--record: needs a window; it cannot be combined with --headless");
  if (options.headless && !options.eventsFile.empty())
    throw UsageError("--events: needs a window; it cannot be combined with --headless");
  if (options.headless && !options.screenshot.empty())
    throw UsageError("--screenshot: needs a window; it cannot be combined with --headless");
}

std::string exitStatusHelp() {
  using namespace exit_code;
  const std::pair<int, const char*> statuses[] = {
      {OK, "success"},
      {RUNTIME_ERROR, "runtime error (an output file could not be written)"},
      {USAGE, "invalid option or value, or an engine that cannot build the scene; nothing was written"},
      {BLEW_UP, "the simulation blew up (a state not finite)"},
      {ODE_ERROR, "ODE reported an error"},
      {MISSING_RESOURCE, "shaders, font or the window module not found"},
      {NO_DISPLAY, "no window could be opened"},
      {ENGINE_FAILED, "the engine failed, not its physics (its process died, answered what is not the protocol, "
                      "or missed a deadline)"},
  };
  std::string text = "Exit status:\n";
  for (const auto& [status, meaning] : statuses) text += "  " + std::to_string(status) + ": " + meaning + "\n";
  return text + "  128 + N: stopped by signal N (SIGHUP 129, SIGINT 130, SIGUSR1 138, SIGALRM 142, SIGTERM 143)\n";
}

std::string keysHelp(const AbstractWindow& scene) {
  std::string text = "Keys (in the window):\n";
  for (const auto& line : scene.helpLines()) text += "  " + line + "\n";
  return text;
}

}  // namespace odelab::cli
