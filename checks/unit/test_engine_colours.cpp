// Every engine a program can run has its own colour, told from every other
// engine's at a glance, and a legend entry naming it: the compare window
// keys outlines, labels, plot curves and a world body's edges by it
// (utils/render/EngineColours.h).

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "Adapters.h"
#include "render/EngineColours.h"
#include "world/EngineCatalog.h"

namespace {

using namespace odelab;

// The names list every program's --engine takes: ODE and the catalogue's
// (built or not: an engine not built here still gets a colour).
std::vector<std::string> everyEngine() {
  std::vector<std::string> names{"ode"};
  for (const world::EngineInfo& info : engines::catalog().list()) names.push_back(info.name);
  return names;
}

// Two colours this far apart in RGB (0-255 a channel) are told apart on the
// sky and on the plot's dark box without looking twice; orange beside red
// or cyan beside light blue are closer than this.
constexpr double LEAST_RGB_DISTANCE = 100.0;

double distance(const EngineColour& a, const EngineColour& b) {
  const double dr = a.r - b.r, dg = a.g - b.g, db = a.b - b.b;
  return std::sqrt(dr * dr + dg * dg + db * db);
}

TEST(EngineColours, EveryEngineInTheNamesListHasItsOwnColour) {
  const std::vector<std::string> engines = everyEngine();
  ASSERT_GE(engines.size(), 7u) << "the names list should hold ode, bullet, mujoco, havok, jolt, rapier, physx";
  std::set<std::string> names;
  for (const std::string& engine : engines) {
    EXPECT_TRUE(hasOwnColour(engine)) << engine << " falls to the fallback white: give it a colour";
    EXPECT_TRUE(names.insert(engineColour(engine).name).second)
        << engine << "'s colour name '" << engineColour(engine).name << "' is another engine's too";
  }
  for (size_t i = 0; i < engines.size(); ++i)
    for (size_t j = i + 1; j < engines.size(); ++j)
      EXPECT_GE(distance(engineColour(engines[i]), engineColour(engines[j])), LEAST_RGB_DISTANCE)
          << engines[i] << " (" << engineColour(engines[i]).name << ") and " << engines[j] << " ("
          << engineColour(engines[j]).name << ") are too alike to tell apart";
}

TEST(EngineColours, TheLegendNamesEveryEngineWithItsColour) {
  const std::vector<std::string> engines = everyEngine();
  const std::string legend = colourLegend(engines);
  for (const std::string& engine : engines) {
    const std::string entry = engine + " " + engineColour(engine).name;
    EXPECT_NE(legend.find(entry), std::string::npos) << "the legend '" << legend << "' lacks '" << entry << "'";
  }
}

TEST(EngineColours, AnEngineKeepsItsColourWhateverItsPlace) {
  // Keyed by the name, not by the place in --compare: jolt is the same
  // colour named first as named last.
  const std::string first = colourLegend({"ode", "jolt", "bullet"});
  const std::string last = colourLegend({"ode", "bullet", "havok", "rapier", "jolt"});
  const std::string jolt = std::string("jolt ") + engineColour("jolt").name;
  EXPECT_NE(first.find(jolt), std::string::npos);
  EXPECT_NE(last.find(jolt), std::string::npos);
}

}  // namespace
