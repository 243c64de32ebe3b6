#pragma once

#include <memory>
#include <string>
#include <vector>

#include "AbstractWindow.h"
#include "CompareLanes.h"
#include "WindowModule.h"

namespace odelab {

// --compare bullet,jolt: one headless run of the same scene on ODE and on
// each engine named, stepped in lockstep (doc/peers.md, "Several engines in
// one run"). Each engine gets a scene of its own, made and parsed from the
// same command line as ODE's, so each measures exactly what
// `testN --engine E --headless` with the same options measures.
//
// Lockstep: each scene runs its own headless run (runHeadless(), the
// scene's, so test7's throws and test10's launches too) on a thread of its
// own, but only one thread runs at a time: before every step a scene hands
// the turn to the next (AbstractWindow::Lockstep), so every engine takes its
// step k before any takes step k + 1, ODE first. An engine whose run ends
// (its seconds done, a blow-up) leaves the turns; the others go on.
//
// In a window (runWindow) the lanes are stepped by the frame loop instead:
// ODE's scene leads and the others follow (CompareLanes).
//
// Reports: every engine's metrics under its name, "ode.steps",
// "bullet.steps", ... (addPrefixed, SceneVisits.h), with
// "<engine>.exit_status" (the status its own run would have ended with) and
// "engines" (how many ran). The run's status is the worst of the engines':
// the highest (0 all well, 3 a blow-up, 4 an ODE error, 128 + N a signal).
// ODE's output files are where its own run writes them; every other
// engine's are in <out-dir>/<engine>/ (compareFolder).

// The list --compare takes: engine names split at commas, each known and
// available here (cli::requireAvailableEngine), not "ode" (which always runs
// first), none twice, at most six. Throws UsageError naming the engine.
std::vector<std::string> parseCompareList(const std::string& list);

// <outDir>/<engine>: made when missing; a symbolic link or anything but a
// writable folder there is refused (UsageError).
std::string compareFolder(const std::string& outDir, const std::string& engine);

class CompareRun {
 public:
  CompareRun();
  ~CompareRun();
  CompareRun(const CompareRun&) = delete;
  CompareRun& operator=(const CompareRun&) = delete;

  // Another engine's scene, its command line parsed and its options set
  // (setRunOptions: engine, out-dir). In the order given.
  void add(const std::string& engine, std::unique_ptr<AbstractWindow> scene);
  // Builds every scene (ODE's, the runner's own, first), runs them in
  // lockstep, prints every engine's metrics under its prefix and writes
  // them to options.metricsJson. Returns the worst status. An ODE error in
  // any engine's scene ends the program as the runner's own handler does
  // (status 4) once the others have reported.
  int run(AbstractWindow& ode, const RunOptions& options);
  // The compare window (doc/manual.md, "Engines side by side"): ODE's scene
  // leads and every other engine's follows it step for step with the same
  // inputs (CompareLanes), each in a view of `window`. At its end each
  // engine's files are ended and its metrics reported as run() reports
  // them; an engine that stopped following (a blow-up, an ODE error) has
  // the status and incomplete files its own run would have. Returns the
  // worst status.
  int runWindow(AbstractWindow& ode, const RunOptions& options, const WindowModule& window);
  // Every other engine's output files end "incomplete: ...; why" (a failure
  // that ends the run before they have).
  void markCutShort(const std::string& why);
  // Destroys every other engine's scene and world: before dCloseODE().
  void close();

 private:
  struct Lane;
  // Every engine's report, ODE's first, each metric under the engine's
  // name; printed and written to options.metricsJson. The worst status.
  int report(const std::vector<Lane*>& lanes, const RunOptions& options);
  int finishWindow(AbstractWindow& ode, const RunOptions& options, int status);
  std::vector<std::unique_ptr<Lane>> others_;
  std::unique_ptr<CompareLanes> windowLanes_;
};

}  // namespace odelab
