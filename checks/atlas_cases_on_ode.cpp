// Every accuracy-atlas case (doc/atlas/*.json) run on ODE in this process,
// as `odelab --world CASE --headless` runs it (the file's step and its
// duration), and every probe's `expect` held to the tolerance the case
// states. Where ODE is known to miss a case's answer, doc/atlas/ode-known.csv
// records the figure it gives instead: the check then asserts that figure
// (so a change in ODE's answer, better or worse, is seen) and that it is
// still outside the case's tolerance (so a record that no longer describes a
// failure is taken out rather than kept).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "Metrics.h"
#include "world/WorldFileScene.h"
#include "world/WorldJson.h"

namespace {

using namespace odelab;
namespace fs = std::filesystem;

fs::path atlasFolder() { return fs::path(ODELAB_ATLAS_DIR); }

std::vector<std::string> caseNames() {
  std::vector<std::string> names;
  for (const auto& item : fs::directory_iterator(atlasFolder()))
    if (item.path().extension() == ".json") names.push_back(item.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

// ODE's known misses: (case, probe) -> the figure ODE gives and the band it
// is held to (doc/atlas/ode-known.csv: case,probe,step_s,ode_value,band,why).
struct KnownMiss {
  double step = 0.0, value = 0.0, band = 0.0;
};

std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) cells.push_back(std::exchange(cell, {}));
    else cell += c;
  }
  cells.push_back(cell);
  return cells;
}

std::map<std::pair<std::string, std::string>, KnownMiss> knownMisses() {
  std::map<std::pair<std::string, std::string>, KnownMiss> misses;
  std::ifstream in(atlasFolder() / "ode-known.csv");
  std::string line;
  std::getline(in, line);  // the header
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const std::vector<std::string> c = splitCsvLine(line);
    if (c.size() < 5) throw std::runtime_error("ode-known.csv: a short row: " + line);
    misses[{c[0], c[1]}] = KnownMiss{std::stod(c[2]), std::stod(c[3]), std::stod(c[4])};
  }
  return misses;
}

struct Folder {
  fs::path path;
  Folder() {
    std::string pattern = (fs::temp_directory_path() / "odelab-atlas-XXXXXX").string();
    path = mkdtemp(pattern.data());
  }
  ~Folder() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

class AtlasCaseOnOde : public testing::TestWithParam<std::string> {};

TEST_P(AtlasCaseOnOde, MeetsItsAnalyticAnswer) {
  const fs::path file = atlasFolder() / (GetParam() + ".json");
  const world::World w = world::readWorldFile(file.string());
  ASSERT_GT(w.duration, 0.0) << file << ": an atlas case states its duration";
  ASSERT_FALSE(w.description.empty()) << file << ": an atlas case states its law in its description";
  Folder folder;
  world::WorldFileScene scene(w);
  RunOptions options;
  options.headless = true;
  options.outDir = folder.path.string();
  scene.initialize(options);
  ASSERT_TRUE(scene.runFor(w.duration)) << file << ": the run stopped before its duration";
  const Metrics metrics = scene.metrics();
  scene.shutdown();

  const auto misses = knownMisses();
  int expects = 0;
  for (const world::Measure& m : w.measures) {
    if (m.kind != world::MeasureKind::Probe || std::isnan(m.expect)) continue;
    ++expects;
    const double value = metrics.get(m.name + "_value");
    const double tolerance = metrics.get(m.name + "_tolerance");
    const auto miss = misses.find({GetParam(), m.name});
    if (miss == misses.end()) {
      EXPECT_NEAR(value, m.expect, tolerance) << GetParam() << ": " << m.name << " at step " << w.settings.step << " s";
      EXPECT_EQ(metrics.get(m.name + "_within"), 1.0) << GetParam() << ": " << m.name;
    } else {
      // A known miss: the recorded figure, at the recorded step, and still a miss.
      EXPECT_EQ(miss->second.step, w.settings.step) << GetParam() << ": " << m.name << " was recorded at another step";
      EXPECT_NEAR(value, miss->second.value, miss->second.band)
          << GetParam() << ": " << m.name << ": ODE's figure moved from the one doc/atlas/ode-known.csv records";
      EXPECT_GT(std::abs(value - m.expect), tolerance)
          << GetParam() << ": " << m.name << " now meets its answer: take its row out of doc/atlas/ode-known.csv";
      EXPECT_EQ(metrics.get(m.name + "_within"), 0.0) << GetParam() << ": " << m.name;
    }
  }
  EXPECT_GT(expects, 0) << file << ": an atlas case states at least one expect";
}

INSTANTIATE_TEST_SUITE_P(Atlas, AtlasCaseOnOde, testing::ValuesIn(caseNames()),
                         [](const testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// Every row of ode-known.csv names a case and a probe with an expect: a row
// left behind by a renamed case would otherwise excuse nothing, silently.
TEST(AtlasKnownMisses, EveryRowNamesAProbeWithAnExpect) {
  for (const auto& [key, miss] : knownMisses()) {
    const fs::path file = atlasFolder() / (key.first + ".json");
    ASSERT_TRUE(fs::exists(file)) << "ode-known.csv names " << key.first << ", which doc/atlas/ does not hold";
    const world::World w = world::readWorldFile(file.string());
    const bool found = std::any_of(w.measures.begin(), w.measures.end(), [&](const world::Measure& m) {
      return m.kind == world::MeasureKind::Probe && m.name == key.second && !std::isnan(m.expect);
    });
    EXPECT_TRUE(found) << "ode-known.csv names " << key.first << "'s " << key.second << ", not a probe with an expect there";
  }
}

}  // namespace
