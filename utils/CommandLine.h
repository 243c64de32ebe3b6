#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <functional>
#include <deque>
#include <stdexcept>
#include <string>
#include <vector>

#include "AbstractWindow.h"

namespace odelab {

// A bad option value found after parsing (e.g. an unwritable --out-dir).
// Like CLI11's own errors it ends the run with exit_code::USAGE before
// anything is written.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

namespace cli {

// Accepts finite numbers within [min, max]; rejects NaN, inf and text, with
// a message that names the allowed range. (CLI::Range lets NaN through.)
CLI::Validator finiteRange(double min, double max);
// Finite and strictly above zero, at most `max`.
CLI::Validator positive(double max = 1e12);
// A whole number within [min, max].
CLI::Validator integerRange(int min, int max);

// Adds --headless, --seconds, --seed, --out-dir, --metrics-json,
// --screenshot, --frames, --shader-dir, --font, --width, --height and the
// window options below.
void addCommonOptions(CLI::App& app, RunOptions& options);
// --max-frame-time, --max-fps, --no-vsync, --text-size, --hud, --no-panel.
void addWindowOptions(CLI::App& app, RunOptions& options);

// An option for every knob that names one (the world settings, the contact
// choices, the scene's), checked against the knob's range or choices
// (utils/Knob.h), default shown in --help.
void addKnobOptions(CLI::App& app, std::deque<Knob>& knobs);
// After parsing: an interval knob given below one step is refused (a row,
// spawn or throw that no step separates), and a knob given without the flag
// it only works with. Throws UsageError naming the option.
void checkKnobs(const CLI::App& app, const std::deque<Knob>& knobs, double step);
// --list-settings: every knob as a JSON array (name, option, key, range or
// choices, default, kind, unit, panel group, header key, metric name).
std::string settingsJson(const std::deque<Knob>& knobs);

// --engine NAME: a known engine available here, or UsageError naming it,
// why it is missing and how to install it.
// `option` names the option in the message (--compare's list uses the same check).
void requireAvailableEngine(const std::string& name, const std::string& option = "--engine");
// --list-engines: one block per engine.
std::string enginesText();

// Makes every option that takes a value refuse an empty one ("--seed=").
// Call after every option is added.
// Also makes every whole-number option (type INT or UINT) decimal only:
// "010" is 10, "08" is 8, "0x10" is refused.
void rejectEmptyValues(CLI::App& app);
// The transform behind that: digits with an optional sign, leading zeros dropped.
CLI::Validator decimalInteger();

// Checks that need the file system: --out-dir is a writable directory, the
// folders of --metrics-json and --screenshot exist and are writable, and the
// window-only options are not combined with --headless. Throws UsageError.
void validateRunOptions(const RunOptions& options);

// An interval (between rows, between throws) below one step: a row or a
// throw that no step separates. Throws UsageError naming `option`.
void refuseBelowStep(const char* option, double interval, double step);
// --seconds shorter than one step, a run of no step. Throws UsageError.
void refuseRunShorterThanStep(const RunOptions& options, double step);
// The same for a run length given as `seconds` (0 or less: not given).
void refuseRunShorterThanStep(double seconds, double step);
// FILE (of `option`) will be replaced whole by a rename at the run's end:
// whyNotWritable (SafeFile.h) must find nothing against it (no folder,
// device, FIFO, link or hard link; its folder there and taking its hidden
// temporary file), so the run never fails late. Throws UsageError.
void requireReplaceableFile(const char* option, const std::string& file);

// Parses the command line the one way every program does (the ODE programs
// and the peers): CLI11's parse, then `checks` (which throw UsageError or a
// CLI::Error). Returns the status to end with at once (0 after --help, 2 for
// a refused command line, its reason on standard error), or nothing when
// the program should go on.
std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv, const std::function<void()>& checks);

// --metrics-json and --screenshot must not name an output file of any scene
// the session can open (`outputNames`, names in --out-dir: the launcher
// passes every scene's), nor a frame --record saves (<test>_frame_NNNNNN.png
// in its folder), nor each other. Throws UsageError.
void refuseOwnOutputs(const RunOptions& options, const std::vector<std::string>& outputNames);
// The streamed outputs this session may open (`outputNames` in --out-dir) meet the
// same rule as the files replaced whole (whyNotWritable): a hard link, a
// symbolic link, a FIFO there is refused before the run. Throws UsageError.
void refuseUnwritableOutputs(const RunOptions& options, const std::vector<std::string>& outputNames);
// No file the run writes (--metrics-json, --screenshot, --export-world,
// `exportWorld`, the outputs `outputNames` in --out-dir, a frame --record
// saves) is one the run reads: `inputs` (the scene's, as (option, path):
// odelab's --world) and the options' own (--events, --font). One file is
// the same path or the same device and inode (sameFile, SafeFile.h).
// Throws UsageError naming both options, before anything is read again or
// written.
void refuseInputsAsOutputs(const RunOptions& options, const std::vector<std::string>& outputNames,
                           const std::vector<std::pair<std::string, std::string>>& inputs,
                           const std::string& exportWorld);

// "Keys:" section for --help, from the scene's key table plus the camera keys.
// The exit statuses (ExitCodes.h) as --help lists them, after the keys.
std::string exitStatusHelp();
std::string keysHelp(const AbstractWindow& scene);

}  // namespace cli
}  // namespace odelab
