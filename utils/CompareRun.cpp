#include "CompareRun.h"

#include <ode/ode.h>

#include <algorithm>
#include <condition_variable>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <system_error>
#ifndef __EMSCRIPTEN__
#include <thread>
#endif

#include "CommandLine.h"
#include "ExitCodes.h"
#include "FormatValue.h"
#include "MeasurementLog.h"
#include "OdeMessages.h"
#include "OpenScene.h"
#include "Platform.h"
#include "SceneVisits.h"
#include "StopSignal.h"
#include "world/Engine.h"

namespace odelab {

namespace {

constexpr size_t MOST_OTHER_ENGINES = 6;  // every engine beside ODE: seven viewports, ODE's first, in the window

#ifndef __EMSCRIPTEN__
// Whose turn it is to step. One lane runs at a time: before each step a
// lane hands the turn to the next lane still running and waits until it
// comes back; a lane that has ended hands it on for good.
class Turns {
 public:
  static constexpr size_t NOBODY = static_cast<size_t>(-1);
  explicit Turns(size_t lanes) : done_(lanes, false), running_(lanes) {}

  void start() {
    const std::lock_guard<std::mutex> lock(mutex_);
    holder_ = 0;
    changed_.notify_all();
  }
  // Threads that never got to run (a thread could not be started): they leave.
  void abandon() {
    const std::lock_guard<std::mutex> lock(mutex_);
    abandoned_ = true;
    changed_.notify_all();
  }
  // False when abandoned.
  bool waitFor(size_t lane) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return holder_ == lane || abandoned_; });
    return !abandoned_;
  }
  void pass(size_t lane) {
    std::unique_lock<std::mutex> lock(mutex_);
    holder_ = next(lane);
    if (holder_ == lane) return;  // the only lane still running
    changed_.notify_all();
    changed_.wait(lock, [&] { return holder_ == lane; });
  }
  void finish(size_t lane) {
    const std::lock_guard<std::mutex> lock(mutex_);
    done_[lane] = true;
    --running_;
    holder_ = running_ ? next(lane) : NOBODY;
    changed_.notify_all();
  }
  void waitForAll() {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return running_ == 0; });
  }

 private:
  size_t next(size_t lane) const {
    for (size_t k = 1; k <= done_.size(); ++k) {
      const size_t candidate = (lane + k) % done_.size();
      if (!done_[candidate]) return candidate;
    }
    return NOBODY;
  }

  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<bool> done_;
  size_t running_;
  size_t holder_ = NOBODY;
  bool abandoned_ = false;
};
#endif

// Columns padded to their widest cell, the last left as it is.
void printTable(std::ostream& out, const std::vector<std::vector<std::string>>& rows) {
  std::vector<size_t> widths;
  for (const auto& row : rows)
    for (size_t c = 0; c + 1 < row.size(); ++c) {
      if (widths.size() <= c) widths.push_back(0);
      widths[c] = std::max(widths[c], row[c].size());
    }
  for (const auto& row : rows) {
    std::string line;
    for (size_t c = 0; c < row.size(); ++c)
      line += c + 1 < row.size() ? row[c] + std::string(widths[c] - row[c].size() + 2, ' ') : row[c];
    out << line << '\n';
  }
}

// The frame loop's figures (frames per second, the longest frame, the
// window's failures) are the window's, in ODE's block; an engine that
// followed ODE's scene has its steps' own wall time, as a headless run has.
Metrics followerMetrics(const AbstractWindow& scene, const CompareLanes::Lane& lane) {
  const Metrics own = scene.metrics();
  Metrics m;
  for (const auto& [name, value] : own.entries()) {
    if (name == "window_fps" || name == "longest_frame_ms" || name == "window_failures") continue;
    if (name == "wall_seconds") m.set(name, lane.steppingSeconds);
    else if (name == "real_time_factor")
      m.set(name, lane.steppingSeconds > 0 ? scene.run().simulatedTime() / lane.steppingSeconds : 0.0);
    else m.setAs(name, own, name);
  }
  for (const auto& [name, texts] : own.texts()) m.setTexts(name, texts);
  return m;
}

}  // namespace

struct CompareRun::Lane {
  std::string engine;
  std::unique_ptr<AbstractWindow> owned;  // empty for ODE's, the runner's own
  AbstractWindow* scene = nullptr;
  bool initialized = false;
  int status = exit_code::OK;
  bool reported = false;
  Metrics metrics;
  std::string error;  // what ended it other than its run's end or a blow-up
  bool odeError = false;

  // The scene's own headless run, and what the runner does when it fails.
  void run() {
    try {
      status = scene->runHeadless();
    } catch (const OdeError& failure) {
      // As the runner: ODE's state is not trusted after its own error, so
      // this world is left as it is (the program ends once all have reported).
      error = failure.what();
      odeError = true;
      status = exit_code::ODE_ERROR;
      odelab::markCutShort(*scene, std::string("ODE error: ") + failure.what());
    } catch (const world::EngineError& failure) {
      error = failure.what();
      const bool failed = dynamic_cast<const world::EngineFailure*>(&failure) != nullptr;
      status = failed ? exit_code::ENGINE_FAILED : exit_code::USAGE;
      odelab::markCutShort(*scene, failed ? "engine failure: " + error : error);
    } catch (const UsageError& failure) {
      error = failure.what();
      status = exit_code::USAGE;
      odelab::markCutShort(*scene, failure.what());
    } catch (const std::exception& failure) {
      error = failure.what();
      status = exit_code::RUNTIME_ERROR;
      odelab::markCutShort(*scene, failure.what());
    }
  }
};

std::vector<std::string> parseCompareList(const std::string& list) {
  std::vector<std::string> names;
  size_t start = 0;
  for (;;) {
    const size_t comma = list.find(',', start);
    const std::string name = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (name.empty())
      throw UsageError("--compare: an empty engine name in '" + list +
                       "'; name the engines with commas between them, as --compare bullet,jolt");
    if (name == "ode")
      throw UsageError("--compare ode: ODE runs first in every compare run; name only the other engines");
    if (std::find(names.begin(), names.end(), name) != names.end())
      throw UsageError("--compare " + name + ": named twice");
    cli::requireAvailableEngine(name, "--compare");
    names.push_back(name);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (names.size() > MOST_OTHER_ENGINES)
    throw UsageError("--compare: at most " + std::to_string(MOST_OTHER_ENGINES) + " engines beside ODE; " +
                     std::to_string(names.size()) + " named");
  return names;
}

std::string compareFolder(const std::string& outDir, const std::string& engine) {
  const std::string folder = joinPath(outDir, engine);
  platform::FileKind kind = platform::fileKind(folder);
  if (kind == platform::FileKind::Absent) {
    std::error_code failed;
    std::filesystem::create_directory(folder, failed);
    if (failed)
      throw UsageError("--compare " + engine + ": cannot make '" + folder + "' for its output files: " + failed.message());
    kind = platform::fileKind(folder);
  }
  if (kind != platform::FileKind::Folder)
    throw UsageError("--compare " + engine + ": '" + folder + "', the folder of its output files, " +
                     (kind == platform::FileKind::Regular ? std::string("is a file") : platform::describe(kind)) +
                     "; remove it or give another --out-dir");
  return folder;
}

CompareRun::CompareRun() = default;
CompareRun::~CompareRun() { close(); }

void CompareRun::add(const std::string& engine, std::unique_ptr<AbstractWindow> scene) {
  auto lane = std::make_unique<Lane>();
  lane->engine = engine;
  lane->scene = scene.get();
  lane->owned = std::move(scene);
  others_.push_back(std::move(lane));
}

int CompareRun::run(AbstractWindow& ode, const RunOptions& options) {
  Lane first;
  first.engine = "ode";
  first.scene = &ode;
  std::vector<Lane*> lanes{&first};
  for (const auto& lane : others_) lanes.push_back(lane.get());

  // Every scene built before any steps, ODE's first: an engine that cannot
  // build the scene refuses the run here, as its own run would, and no
  // engine's output file has been opened yet (the hold is released only
  // once every scene is built).
  {
    StreamedFile::Hold outputsHeld;
    for (Lane* lane : lanes) {
      const RunOptions own = lane->scene->options();
      lane->initialized = true;
      lane->scene->initialize(own);
    }
    outputsHeld.release();
  }
  // Each report is kept for the one below, not printed or written.
  const auto keepReport = [](Lane* lane) {
    return [lane](const Metrics& metrics) {
      lane->metrics = metrics;
      lane->reported = true;
    };
  };

#ifdef __EMSCRIPTEN__
  // No threads in the browser's build: one engine's run after another (the
  // same figures; no lockstep).
  for (Lane* lane : lanes) {
    lane->scene->runInLockstep({{}, keepReport(lane)});
    lane->run();
  }
#else
  Turns turns(lanes.size());
  for (size_t i = 0; i < lanes.size(); ++i)
    lanes[i]->scene->runInLockstep({[&turns, i] {
                                      turns.pass(i);
                                      OdeMessages::adoptThread();
                                    },
                                    keepReport(lanes[i])});
  std::vector<std::thread> threads;
  try {
    for (size_t i = 0; i < lanes.size(); ++i)
      threads.emplace_back([&turns, i, lane = lanes[i]] {
        if (!turns.waitFor(i)) return;
        OdeMessages::adoptThread();
        dAllocateODEDataForThread(dAllocateMaskAll);
        lane->run();
        dCleanupODEAllDataForThread();
        turns.finish(i);
      });
  } catch (const std::system_error&) {
    turns.abandon();
    for (std::thread& thread : threads) thread.join();
    OdeMessages::adoptThread();
    throw;
  }
  turns.start();
  turns.waitForAll();
  for (std::thread& thread : threads) thread.join();
  OdeMessages::adoptThread();
#endif

  return report(lanes, options);
}

int CompareRun::runWindow(AbstractWindow& ode, const RunOptions& options, const WindowModule& window) {
  std::vector<std::pair<std::string, AbstractWindow*>> others;
  for (const auto& lane : others_) others.emplace_back(lane->engine, lane->scene);
  windowLanes_ = std::make_unique<CompareLanes>(ode, others);
  return window.runCompare(*windowLanes_, options,
                           [this, &ode, options](int status) { return finishWindow(ode, options, status); });
}

int CompareRun::finishWindow(AbstractWindow& ode, const RunOptions& options, int status) {
  Lane first;
  first.engine = "ode";
  first.scene = &ode;
  std::vector<Lane*> lanes{&first};
  for (const auto& lane : others_) lanes.push_back(lane.get());
  for (Lane* lane : lanes) lane->initialized = lane->scene->run().world() != nullptr;
  if (stopSignal() != 0) {
    int signalled = exit_code::OK;
    for (Lane* lane : lanes)
      if (lane->initialized) signalled = lane->scene->stoppedBySignal();
    return signalled;
  }
  if (status != exit_code::OK) {
    const std::string why = "the window run failed with status " + std::to_string(status) + " (see standard error)";
    for (Lane* lane : lanes)
      if (lane->initialized) odelab::markCutShort(*lane->scene, why);
    return status;
  }
  for (size_t i = 0; i < lanes.size(); ++i) {
    Lane& lane = *lanes[i];
    const std::string& failure = windowLanes_->lanes()[i].failure;
    lane.scene->endOutputs(failure);
    lane.error = failure;
    lane.odeError = failure.rfind("ODE error", 0) == 0;
    lane.status = failure.empty() ? exit_code::OK : lane.odeError ? exit_code::ODE_ERROR : exit_code::BLEW_UP;
    lane.metrics = i == 0 ? lane.scene->metrics() : followerMetrics(*lane.scene, windowLanes_->lanes()[i]);
    // The window's: how long the slowest input (R) took to reach every engine.
    if (i == 0) lane.metrics.set("longest_input_to_engines_ms", 1000.0 * windowLanes_->longestInputSeconds());
    lane.reported = true;
  }
  return report(lanes, options);
}

int CompareRun::report(const std::vector<Lane*>& lanes, const RunOptions& options) {
  // Every engine's report, ODE's first, each metric under the engine's name.
  const bool stopped = stopSignal() != 0;
  Metrics all;
  all.set("engines", static_cast<double>(lanes.size()));
  int worst = exit_code::OK;
  bool odeError = false;
  // On the terminal a short table, an engine a row: its status, how far it
  // ran, what a step cost (the engine's own calls, and the link outside
  // them beside it, never added: lab/odelab_report/costs.py) and the scene's
  // headline; every metric goes to --metrics-json (some 40 an engine would
  // bury the table).
  std::vector<std::vector<std::string>> table = {
      {"engine", "status", "sim s", "engine ms/step", "link ms/step", "headline"}};
  for (Lane* lane : lanes) {
    worst = std::max(worst, lane->status);
    odeError = odeError || lane->odeError;
    const std::string prefix = lane->engine + ".";
    if (lane->reported) {
      Metrics block;
      addPrefixed(block, prefix, lane->metrics);
      block.set(prefix + "exit_status", lane->status);
      const double steps = lane->metrics.has("steps") ? lane->metrics.get("steps") : 0.0;
      const auto perStep = [&](const char* name) {
        return steps > 0 && lane->metrics.has(name) ? formatValue(1000.0 * lane->metrics.get(name) / steps, 2)
                                                    : std::string("-");
      };
      const std::string headline = lane->scene->headline();
      table.push_back({lane->engine, std::to_string(lane->status), formatValue(lane->metrics.get("sim_seconds")),
                       perStep("engine_wall_seconds"), perStep("link_wall_seconds"),
                       headline.empty() ? "-" : headline});
      addPrefixed(all, "", block);
      if (!lane->error.empty())
        std::cerr << "error: " << lane->engine << ": " << lane->error << '\n';
      else if (!lane->scene->run().blowUpReason().empty())
        std::cerr << "error: " << lane->engine << ": " << lane->scene->run().blowUpReason() << '\n';
    } else {
      all.set(prefix + "exit_status", lane->status);
      table.push_back({lane->engine, std::to_string(lane->status), "-", "-", "-", "did not report"});
      if (!lane->error.empty()) std::cerr << "error: " << lane->engine << ": " << lane->error << '\n';
    }
  }
  std::cout << lanes.front()->scene->title() << ", engines side by side:\n";
  printTable(std::cout, table);
  std::cout << (options.metricsJson.empty() ? "every metric of every engine: add --metrics-json FILE\n"
                                            : "every metric of every engine: " + options.metricsJson + "\n");
  // Stopped by a signal, no engine's run is whole: nothing is written (as one run's).
  if (!stopped && !options.metricsJson.empty()) all.writeJsonAtomically(options.metricsJson);
  if (odeError) {
    // The runner's rule for an ODE error: leave without tearing the worlds down.
    std::cout.flush();
    std::exit(exit_code::ODE_ERROR);
  }
  return worst;
}

void CompareRun::markCutShort(const std::string& why) {
  for (const auto& lane : others_)
    if (lane->initialized) odelab::markCutShort(*lane->scene, why);
}

void CompareRun::close() {
  windowLanes_.reset();
  for (const auto& lane : others_) {
    if (lane->owned) lane->owned->shutdown();
    lane->owned.reset();
    lane->scene = nullptr;
  }
  others_.clear();
}

}  // namespace odelab
