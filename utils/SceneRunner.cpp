#include "SceneRunner.h"

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <optional>
#include <exception>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "CommandLine.h"
#include "CompareRun.h"
#include "CopyLine.h"
#include "ExitCodes.h"
#include "OdeMessages.h"
#include "MeasurementLog.h"
#include "OpenScene.h"
#include "Platform.h"
#include "SceneVisits.h"
#include "StopSignal.h"
#include "SafeFile.h"
#include "WindowModule.h"
#include "world/EngineCatalog.h"
#include "world/WorldJson.h"

namespace odelab {

namespace {

// dInitODE2 / dCloseODE around everything that touches ODE.
class OdeLibrary {
 public:
  OdeLibrary() {
    dInitODE2(0);
    dAllocateODEDataForThread(dAllocateMaskAll);
    OdeMessages::install();
  }
  ~OdeLibrary() { dCloseODE(); }
};

// However a run ends, its output files say so ("# incomplete: ...; why").
// A failure caught here marks them with its message; an ODE error in a pool
// thread marks them through OdeMessages; exit() called inside the run by a
// library (Xlib's, when the display goes away) marks them from an atexit
// hook. OpenScene holds the last two for the scene open, from before its
// first step to its close.

// What follows a window run: the output files' end lines and the metrics,
// every visit's when the window switched scenes (SceneVisits).
int afterWindow(OpenScene& current, const SceneVisits& visits, const RunOptions& options, int status) {
  if (!current.isOpen()) return status == exit_code::OK ? exit_code::RUNTIME_ERROR : status;
  AbstractWindow& scene = current.scene();
  if (stopSignal() != 0) return scene.stoppedBySignal();
  if (status != exit_code::OK) {
    markCutShort(scene, "the window run failed with status " + std::to_string(status) + " (see standard error)");
    return status;
  }
  scene.endOutputs("");
  // A window run reports too, so scripted sessions can be checked.
  if (!options.metricsJson.empty())
    visits.session(scene.programName(), scene.metrics()).writeJsonAtomically(options.metricsJson);
  return status;
}

int run(OpenScene& current, const RunOptions& options, SceneSwitching* switching) {
  AbstractWindow& first = current.scene();
  if (options.headless) {
    first.initialize(options);
    return first.runHeadless();
  }
  // The window builds the scene itself once the window, shaders, font and
  // --events script are ready, so a missing resource leaves no output file.
  // The options by value: in a browser the callback runs after this call.
  const WindowModule* window = windowModule();
  if (!window) return exit_code::MISSING_RESOURCE;
  if (!switching)
    return window->run(first, options, [&current, options](int status) {
      return afterWindow(current, SceneVisits{}, options, status);
    });
  // Each scene the window leaves is ended, measured and closed (OpenScene:
  // its files, locks and hooks let go, the scene destroyed) before the next
  // is made, so a scene shown again opens its files afresh.
  SceneVisits visits;
  return window->runSwitching(
      first, options,
      [&](int offset) -> AbstractWindow& {
        AbstractWindow& ending = current.scene();
        ending.endOutputs("");
        visits.add(ending.programName(), ending.metrics());  // before the world goes: metrics read it
        current.close();
        current.open(switching->next(offset, options));
        return current.scene();
      },
      [&](int status) { return afterWindow(current, visits, options, status); });
}

// --export-world: the scene as built, as data, and nothing run. The scene
// is built headless under a hold on its output files that is never
// released (StreamedFile::Hold): they are never opened, so exporting
// touches no run's files and needs no temporary folder (nothing left in
// TMPDIR when the export is cut short, nothing asked of it).
class ExportWorld {
 public:
  explicit ExportWorld(std::string path) : path_(std::move(path)) {}
  int operator()(AbstractWindow& scene, RunOptions options) {
    const StreamedFile::Hold outputsNeverOpened;
    options.headless = true;
    options.metricsJson.clear();
    scene.initialize(options);
    writeFileAtomically(path_, world::worldToJson(scene.describeWorld()));
    std::cout << "world written: " << path_ << '\n';
    return exit_code::OK;
  }

 private:
  std::string path_;
};

// One scene's command line: the common options, the scene's own, one per
// knob and the runner's. A compare run parses the same arguments once more
// for each engine's scene, each into a command line of its own (the
// scene's options and knobs are its members).
struct SceneCommandLine {
  CLI::App app;
  RunOptions options;
  std::vector<const CLI::Option*> sceneOptions;  // the scene's own, which the copied command line repeats as given
  bool listSettings = false;
  bool listEngines = false;
  std::string engineSetting = "default";
  std::string compare;
  std::string exportWorld;
  bool printCommandLine = false;

  SceneCommandLine(AbstractWindow& scene, const char* description)
      : app{std::string(scene.title()) + "\n" + description} {
    app.get_formatter()->column_width(34);
    cli::addCommonOptions(app, options);
    const size_t sharedOptions = app.get_options().size();
    scene.addOptions(app);
    const std::vector<CLI::Option*> added = app.get_options();
    sceneOptions.assign(added.begin() + static_cast<long>(sharedOptions), added.end());
    cli::addKnobOptions(app, scene.tuning().knobs());
    app.add_flag("--list-settings", listSettings,
                 "print every knob (world settings, contact choices, the scene's) as JSON (name, option, key, range, default, unit, group, header, metric) and exit");
    app.add_flag("--list-engines", listEngines,
                 "print every engine --engine takes: whether it is here, its version and precision, what its best "
                 "settings change, and how to install a missing one; then exit");
    app.add_option("--engine", options.engine,
                   "the engine that steps the scene: ode (the default), bullet, mujoco, havok, jolt, rapier or physx; the "
                   "scene's own code measures it (doc/peers.md)")
        ->capture_default_str();
    app.add_option("--engine-setting", engineSetting,
                   "default: the engine as it comes, with the scene's physics translated; best: its documented "
                   "settings for accuracy (--list-engines says which)")
        ->check(CLI::IsMember({"default", "best"}))
        ->capture_default_str();
    app.add_option("--compare", compare,
                   "ENGINE,ENGINE,...: the same run on ODE and on each engine named (up to six), in lockstep: in "
                   "the window one view per engine under one camera, every input to every engine; metrics as "
                   "ode.NAME, bullet.NAME, ...; the other engines' files in OUT-DIR/ENGINE/ (doc/peers.md, "
                   "\"Several engines in one run\")");
    app.add_option("--export-world", exportWorld,
                   "write the world as built (bodies, geoms, joints, every pair's contact surface, the settings) "
                   "to FILE as JSON (doc/world-format.md) and exit; odelab --world FILE runs it");
    app.add_flag("--print-command-line", printCommandLine,
                 "at the run's end print \"command line: \" and the command line that starts it again with every "
                 "value it is tuned by then (as the panel's Copy as command line)");
    cli::rejectEmptyValues(app);
    app.footer(cli::keysHelp(scene) + cli::exitStatusHelp());
  }
};

// The folders --compare makes for the other engines' files (OUT-DIR/ENGINE):
// a run refused before it steps (a later engine's folder in the way, an
// engine that cannot build the scene) takes back the ones it made, empty.
class FoldersMadeForRun {
 public:
  void noteIfAbsent(const std::string& folder) {
    if (platform::fileKind(folder) == platform::FileKind::Absent) folders_.push_back(folder);
  }
  void removeEmpty() {
    for (auto folder = folders_.rbegin(); folder != folders_.rend(); ++folder) {
      std::error_code notEmpty;  // a folder something else has written to stays
      std::filesystem::remove(*folder, notEmpty);
    }
    folders_.clear();
  }

 private:
  std::vector<std::string> folders_;
};

// --compare: each other engine's scene, made by `makeAnother` and parsed
// from the same arguments, its files in OUT-DIR/ENGINE. Each command line
// is kept in `lines` for as long as its scene lives (a knob reads its
// option: test10's --launches). A refusal is the status to end with.
std::optional<int> addCompareScenes(CompareRun& compare, std::vector<std::unique_ptr<SceneCommandLine>>& lines,
                                    const RunOptions& options, const char* description, int argc, char** argv,
                                    const std::function<std::unique_ptr<AbstractWindow>()>& makeAnother,
                                    FoldersMadeForRun& made) {
  for (const std::string& engine : options.compare) made.noteIfAbsent(joinPath(options.outDir, engine));
  for (const std::string& engine : options.compare) {
    std::unique_ptr<AbstractWindow> scene = makeAnother();
    lines.push_back(std::make_unique<SceneCommandLine>(*scene, description));
    SceneCommandLine* const line = lines.back().get();
    const std::optional<int> refused = cli::parseCommandLine(line->app, argc, argv, [&] {
      RunOptions& own = line->options;
      own.engine = engine;
      own.engineBest = line->engineSetting == "best";
      own.compare.clear();
      own.outDir = compareFolder(options.outDir, engine);
      cli::refuseOwnOutputs(own, scene->outputFileNames());
      cli::refuseUnwritableOutputs(own, scene->outputFileNames());
      cli::refuseInputsAsOutputs(own, scene->outputFileNames(), scene->inputFiles(), "");
      own.metricsJson.clear();  // the compare run writes every engine's
      cli::checkKnobs(line->app, scene->tuning().knobs(), scene->tuning().settings().step);
      scene->setRunOptions(own);
      scene->checkOptions();
    });
    if (refused) {
      made.removeEmpty();
      return refused;
    }
    scene->session().setGivenSceneOptions(givenOptions(line->sceneOptions));
    compare.add(engine, std::move(scene));
  }
  return std::nullopt;
}

}  // namespace

int runEntry(const SceneEntry& entry, int argc, char** argv, SceneSwitching* switching) {
  std::unique_ptr<AbstractWindow> scene;
  try {
    scene = entry.make();
    if (switching) scene->offerSceneSwitch(switching->scenes(), switching->current());
  } catch (const std::logic_error& error) {
    std::cerr << "error: scene declaration: " << error.what() << '\n';
    return exit_code::RUNTIME_ERROR;
  }
  return runScene(std::move(scene), entry.description, argc, argv, switching, [&entry] { return entry.make(); });
}

int runScene(std::unique_ptr<AbstractWindow> first, const char* description, int argc, char** argv,
             SceneSwitching* switching, const std::function<std::unique_ptr<AbstractWindow>()>& makeAnother) {
  // On the heap, as the command line below: in a browser the window's frames
  // and its end run after this call has left its stack frame to the page
  // (emscripten_set_main_loop), where a local would be overwritten.
  const auto openScene = std::make_unique<OpenScene>(std::move(first));
  OpenScene& current = *openScene;
  AbstractWindow& scene = current.scene();  // the first scene, until the window switches
  const auto line = std::make_unique<SceneCommandLine>(scene, description);
  CLI::App& app = line->app;
  RunOptions& options = line->options;
  const std::string& exportWorld = line->exportWorld;
  const std::optional<int> refused = cli::parseCommandLine(app, argc, argv, [&] {
    cli::validateRunOptions(options);
    options.screenshotAtEnd = !options.screenshot.empty() && options.seconds > 0.0 && app.count("--frames") == 0;
    // The launcher's window may switch to any scene: every scene's files
    // are this session's.
    const std::vector<std::string> outputs = switching ? switching->outputFileNames() : scene.outputFileNames();
    if (!line->compare.empty()) {
      // Before --engine's own check: the two are one or the other.
      if (app.count("--engine") > 0)
        throw UsageError("--compare: ODE runs first and then every engine named; leave out --engine");
      options.compare = parseCompareList(line->compare);
      if (!exportWorld.empty()) throw UsageError("--export-world: the world is ODE's as built; leave out --compare");
      if (!makeAnother) throw UsageError("--compare: this program cannot make its scene again");
    }
    cli::refuseOwnOutputs(options, outputs);
    cli::refuseUnwritableOutputs(options, outputs);
    cli::refuseInputsAsOutputs(options, outputs, scene.inputFiles(), exportWorld);
    cli::refuseRunShorterThanStep(options, scene.tuning().settings().step);
    cli::checkKnobs(app, scene.tuning().knobs(), scene.tuning().settings().step);
    options.engineBest = line->engineSetting == "best";
    if (!exportWorld.empty()) {
      if (options.engine != "ode") throw UsageError("--export-world: the world is ODE's as built; leave out --engine");
      cli::requireReplaceableFile("--export-world", exportWorld);
    }
    if (options.engine != "ode") cli::requireAvailableEngine(options.engine);
    scene.setRunOptions(options);
    scene.checkOptions();
    // The scenes a window may switch to get the same options: checked now,
    // before any scene runs, not when a switch reaches them.
    if (switching && !options.headless) switching->checkOptions(options);
  });
  if (refused) return *refused;
  scene.session().setGivenSceneOptions(givenOptions(line->sceneOptions));

  if (line->listSettings) {
    std::cout << cli::settingsJson(scene.tuning().knobs());
    return exit_code::OK;
  }
  if (line->listEngines) {
    std::cout << cli::enginesText();
    return exit_code::OK;
  }
  // --compare: the other engines' scenes, parsed from the same arguments,
  // before anything runs (doc/peers.md, "Several engines in one run").
  std::vector<std::unique_ptr<SceneCommandLine>> otherLines;  // outlive the scenes that read them
  std::unique_ptr<CompareRun> compare;
  FoldersMadeForRun madeFolders;
  if (!options.compare.empty()) {
    compare = std::make_unique<CompareRun>();
    if (const std::optional<int> refusedOther =
            addCompareScenes(*compare, otherLines, options, description, argc, argv, makeAnother, madeFolders))
      return *refusedOther;
  }
  installStopSignalHandlers();
  std::optional<ExportWorld> exporter;
  if (!exportWorld.empty()) exporter.emplace(exportWorld);
  OdeLibrary ode;
  if (!dCheckConfiguration("ODE_double_precision")) {
    std::cerr << "error: this ODE library is not built in double precision\n";
    return exit_code::RUNTIME_ERROR;
  }
  int status = exit_code::OK;
  current.hook();
  // The scene open when a run fails: after a switch, not the first.
  const auto markOpenScene = [&current, &compare](const std::string& why) {
    if (current.isOpen()) markCutShort(current.scene(), why);
    if (compare) compare->markCutShort(why);
  };
  try {
    if (exporter)
      status = (*exporter)(scene, options);
    else if (compare && options.headless)
      status = compare->run(scene, options);
    else if (compare)
      status = windowModule() ? compare->runWindow(scene, options, *windowModule()) : exit_code::MISSING_RESOURCE;
    else
      status = run(current, options, switching);
  } catch (const world::EngineError& error) {
    // An engine that cannot build the scene refuses it before any step
    // (status 2); one whose process fails, before or while stepping, is an
    // engine failure (status 7), never a blow-up (stepEngine). Either way
    // the output files were held until every scene was built, so a refusal
    // leaves them as they were. A stop signal that came while the engine
    // was being waited for ends the run as any stop does.
    if (stopSignal() != 0) {
      status = current.isOpen() ? current.scene().stoppedBySignal() : 128 + stopSignal();
      if (compare) compare->markCutShort(std::string("stopped by ") + stopSignalName());
    } else {
      const bool failed = dynamic_cast<const world::EngineFailure*>(&error) != nullptr;
      std::cerr << "error: " << error.what() << '\n';
      markOpenScene(failed ? "engine failure: " + std::string(error.what()) : std::string(error.what()));
      status = failed ? exit_code::ENGINE_FAILED : exit_code::USAGE;
    }
  } catch (const OdeError& error) {
    // ODE's state is not to be trusted after its own error: tearing the
    // world down can raise another one from a destructor. Leave without
    // unwinding; output files are flushed row by row already.
    std::cerr << "error: " << error.what() << '\n';
    markOpenScene(std::string("ODE error: ") + error.what());
    std::cout.flush();
    std::exit(exit_code::ODE_ERROR);
  } catch (const UsageError& error) {
    std::cerr << "error: " << error.what() << '\n';
    markOpenScene(error.what());
    status = exit_code::USAGE;
  } catch (const std::exception& error) {
    std::cerr << "error: " << error.what() << '\n';
    markOpenScene(error.what());
    status = exit_code::RUNTIME_ERROR;
  }
  if (line->printCommandLine && current.isOpen()) std::cout << "command line: " << copyLine(current.scene()) << std::endl;
  if (compare) compare->close();  // while ODE is still initialised
  current.close();
  if (status == exit_code::USAGE || status == exit_code::ENGINE_FAILED) madeFolders.removeEmpty();
  return status;
}

}  // namespace odelab
