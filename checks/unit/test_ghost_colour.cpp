// The analytic ghost's colour is no engine's: it is as far from each
// engine's colour, and from the white an unknown engine falls to, as the
// engines are from one another (test_engine_colours.cpp's least distance),
// so a ghost is never read as an engine's body.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "Adapters.h"
#include "render/EngineColours.h"
#include "world/EngineCatalog.h"

namespace {

using namespace odelab;

constexpr double LEAST_RGB_DISTANCE = 100.0;

double distance(const EngineColour& a, const EngineColour& b) {
  const double dr = a.r - b.r, dg = a.g - b.g, db = a.b - b.b;
  return std::sqrt(dr * dr + dg * dg + db * db);
}

TEST(GhostColour, IsNoEnginesColour) {
  std::vector<std::string> engines{"ode", "an-engine-without-a-colour"};
  for (const world::EngineInfo& info : engines::catalog().list()) engines.push_back(info.name);
  for (const std::string& engine : engines) {
    EXPECT_GE(distance(ghostColour(), engineColour(engine)), LEAST_RGB_DISTANCE)
        << "the ghost's " << ghostColour().name << " is too like " << engine << "'s " << engineColour(engine).name;
    EXPECT_NE(std::string(ghostColour().name), engineColour(engine).name);
  }
}

}  // namespace
