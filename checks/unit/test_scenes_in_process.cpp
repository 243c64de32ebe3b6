// Every scene of the registry, run in this process as its program runs it
// headless: the same steps give the same state (two instances, and one made
// again by reset()), and the very state the program reports for the same
// run. The scene's own code is tested here without a process between; the
// process checks keep what only a process shows (options, exit statuses,
// files, signals).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <iterator>
#include <set>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "Metrics.h"
#include "SceneRegistry.h"
#include "SceneRunner.h"

namespace {

using namespace odelab;
namespace fs = std::filesystem;

constexpr long long STEPS = 400;

// A folder of its own for a scene's output files (test2 and test8 write
// one), removed at the end.
struct ScratchFolder {
  fs::path path;
  explicit ScratchFolder(const std::string& name) {
    std::string pattern = (fs::temp_directory_path() / ("odelab-in-process-" + name + "-XXXXXX")).string();
    path = mkdtemp(pattern.data());
  }
  ~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

struct InProcessRun {
  std::uint64_t hash;
  double step;
};

std::unique_ptr<AbstractWindow> made(const SceneEntry& entry, const fs::path& outDir, double seconds = 0.0) {
  std::unique_ptr<AbstractWindow> scene = entry.make();
  RunOptions options;
  options.headless = true;
  options.outDir = outDir.string();
  if (seconds > 0) options.seconds = seconds;
  scene->initialize(options);
  return scene;
}

// STEPS steps one by one, as a window's frames make them (after half as
// many and R when `resetHalfway`).
InProcessRun runInProcess(const SceneEntry& entry, const fs::path& outDir, bool resetHalfway = false) {
  std::unique_ptr<AbstractWindow> scene = made(entry, outDir);
  if (resetHalfway) {
    for (long long i = 0; i < STEPS / 2; ++i) scene->stepOnce();
    scene->reset();
  }
  for (long long i = 0; i < STEPS; ++i) scene->stepOnce();
  const InProcessRun run{scene->run().stateHash(), scene->tuning().settings().step};
  scene->shutdown();
  return run;
}

const SceneEntry& entryNamed(const std::string& name) {
  const SceneEntry* entry = findScene(name);
  if (!entry) throw std::runtime_error("no scene " + name);
  return *entry;
}

std::vector<std::string> sceneNames() {
  std::vector<std::string> names;
  for (const SceneEntry& entry : sceneRegistry()) names.push_back(entry.name);
  return names;
}

class SceneInProcess : public testing::TestWithParam<std::string> {};

TEST_P(SceneInProcess, TheSameStepsGiveTheSameState) {
  const SceneEntry& entry = entryNamed(GetParam());
  ScratchFolder first(GetParam()), second(GetParam());
  EXPECT_EQ(runInProcess(entry, first.path).hash, runInProcess(entry, second.path).hash);
}

TEST_P(SceneInProcess, ResetBuildsTheSameStartAgain) {
  const SceneEntry& entry = entryNamed(GetParam());
  ScratchFolder first(GetParam()), second(GetParam());
  EXPECT_EQ(runInProcess(entry, first.path).hash, runInProcess(entry, second.path, true).hash)
      << "half a run, R, then the run: another state than the run alone";
}

Metrics readMetrics(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return parseMetricsJson(text.str());
}

// The program's own path (runEntry: the command line, the scene's checks,
// runHeadless with the scene's own run where it has one, as test7's throws
// and test10's launches), here and in the program: the same steps and the
// same state.
TEST_P(SceneInProcess, IsTheRunItsProgramMakes) {
  const SceneEntry& entry = entryNamed(GetParam());
  ScratchFolder here(GetParam()), there(GetParam());
  std::ostringstream seconds;
  seconds.precision(17);
  seconds << static_cast<double>(STEPS) * entry.make()->tuning().settings().step;
  const auto arguments = [&](const fs::path& folder) {
    return std::vector<std::string>{entry.name, "--headless", "--seconds", seconds.str(), "--out-dir", folder.string(),
                                    "--metrics-json", (folder / "metrics.json").string()};
  };
  std::vector<std::string> mine = arguments(here.path);
  std::vector<char*> argv;
  for (std::string& argument : mine) argv.push_back(argument.data());
  testing::internal::CaptureStdout();  // the run's report
  const int status = runEntry(entry, static_cast<int>(argv.size()), argv.data());
  testing::internal::GetCapturedStdout();
  ASSERT_EQ(status, 0);

  const std::vector<std::string> theirs = arguments(there.path);
  std::string command = std::string(ODELAB_PROGRAMS_DIR) + "/" + entry.name;
  for (size_t i = 1; i < theirs.size(); ++i) command += " " + theirs[i];
  command += " >/dev/null 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const Metrics inProcess = readMetrics(here.path / "metrics.json");
  const Metrics program = readMetrics(there.path / "metrics.json");
  EXPECT_EQ(inProcess.get("steps"), program.get("steps")) << command;
  EXPECT_EQ(inProcess.get("state_hash"), program.get("state_hash")) << command;
}

// A window's frames (stepOnce: inputs due, the drag, rewind's marks) and a
// headless run (runFor) make the same state from the same steps.
TEST_P(SceneInProcess, AWindowsStepsAreTheHeadlessRunsSteps) {
  const SceneEntry& entry = entryNamed(GetParam());
  ScratchFolder first(GetParam()), second(GetParam());
  const InProcessRun stepped = runInProcess(entry, first.path);
  std::unique_ptr<AbstractWindow> scene = made(entry, second.path);
  scene->runFor(static_cast<double>(STEPS) * stepped.step);
  EXPECT_EQ(scene->run().stateHash(), stepped.hash);
  scene->shutdown();
}

// Every knob, declared once, reaches every report: its option, the output
// header (settingsDescription(), and the header of every output file the
// scene writes), the metric knob_<name>, each under a name of its own.
TEST_P(SceneInProcess, EveryKnobReachesEveryReport) {
  const SceneEntry& entry = entryNamed(GetParam());
  ScratchFolder folder(GetParam());
  std::unique_ptr<AbstractWindow> scene = made(entry, folder.path);
  for (int i = 0; i < 10; ++i) scene->stepOnce();
  const Metrics metrics = scene->metrics();
  const auto description = scene->settingsDescription();
  std::set<std::string> names, headers;
  for (const auto& [key, text] : description) EXPECT_TRUE(headers.insert(key).second) << "header key twice: " << key;
  std::vector<std::string> files;
  for (const auto& file : fs::directory_iterator(folder.path)) {
    std::ifstream in(file.path());
    files.push_back(std::string(std::istreambuf_iterator<char>(in), {}));
  }
  for (const Knob& knob : scene->tuning().knobs()) {
    EXPECT_TRUE(names.insert(knob.name).second) << "knob name twice: " << knob.name;
    EXPECT_EQ(knob.option.rfind("--", 0), 0u) << knob.name << ": no option";
    ASSERT_TRUE(metrics.has("knob_" + knob.name)) << knob.name;
    EXPECT_EQ(metrics.get("knob_" + knob.name), knob.metricValue()) << knob.name;
    const std::pair<std::string, std::string> line{knob.headerKey(), knob.headerText()};
    EXPECT_NE(std::find(description.begin(), description.end(), line), description.end()) << knob.name;
    for (const std::string& text : files) {
      if (text.rfind("# ", 0) == 0) {
        EXPECT_NE(text.find("# " + line.first + ": " + line.second + "\n"), std::string::npos)
            << knob.name << " not in an output file's header:\n" << text.substr(0, 2000);
      }
    }
  }
  scene->shutdown();
}

// Rewind rebuilds a state by replaying the run's recorded inputs from its
// start: every knob a person changes mid-run (each to its key's next value;
// not those that rebuild the scene, which start a new run) is put back to
// its start value and replayed, so the replay ends in the very state.
TEST_P(SceneInProcess, ARewindReplaysEveryKnobChange) {
  const SceneEntry& entry = entryNamed(GetParam());
  ScratchFolder folder(GetParam());
  std::unique_ptr<AbstractWindow> scene = made(entry, folder.path);
  for (int i = 0; i < 50; ++i) scene->stepOnce();
  const auto& knobs = scene->tuning().knobs();
  int changed = 0;
  for (int i = 0; i < static_cast<int>(knobs.size()); ++i) {
    const Knob& knob = knobs[static_cast<size_t>(i)];
    if (knob.rebuilds || knob.headlessOnly) continue;
    const double before = knob.get();
    scene->changeKnob(i, knob.next(+1));
    if (knob.get() != before) ++changed;
  }
  EXPECT_GT(changed, 0);
  for (int i = 0; i < 100; ++i) scene->stepOnce();
  const std::uint64_t hash = scene->run().stateHash();
  const long long steps = scene->run().steps();
  scene->replayTo(steps);
  EXPECT_EQ(scene->run().steps(), steps);
  EXPECT_EQ(scene->run().stateHash(), hash) << changed << " knobs changed at step 50";
  scene->shutdown();
}

INSTANTIATE_TEST_SUITE_P(EveryScene, SceneInProcess, testing::ValuesIn(sceneNames()),
                         [](const testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
