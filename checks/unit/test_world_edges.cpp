// A world file's bodies ask to be drawn with their edges (in the view's
// engine colour, by the compare views' outline): three boxes stacked in a
// column read as three in every view, not as one block of colour. The
// ground plane has no edges to draw.

#include <gtest/gtest.h>

#include <stdlib.h>

#include <filesystem>
#include <string>

#include "world/WorldFileScene.h"
#include "world/WorldJson.h"

namespace {

using namespace odelab;
namespace fs = std::filesystem;

const char* const STACK = R"({
  "format": "odelab-world", "version": 1,
  "settings": {"step": 0.001, "gravity": [0, -9.81, 0]},
  "bodies": [
    {"mass": 1, "inertia": [0.01, 0.01, 0.01, 0, 0, 0], "position": [0, 0.1, 0]},
    {"mass": 1, "inertia": [0.01, 0.01, 0.01, 0, 0, 0], "position": [0, 0.3, 0]},
    {"mass": 1, "inertia": [0.01, 0.01, 0.01, 0, 0, 0], "position": [0, 0.5, 0]}
  ],
  "geoms": [
    {"shape": "plane", "body": -1, "plane": [0, 1, 0, 0]},
    {"shape": "box", "body": 0, "size": [0.2, 0.2, 0.2]},
    {"shape": "box", "body": 1, "size": [0.2, 0.2, 0.2]},
    {"shape": "sphere", "body": 2, "radius": 0.1},
    {"shape": "box", "body": -1, "size": [1, 0.1, 1], "position": [2, 0.05, 0]}
  ],
  "surfaces": [{"mu": 0.5}]
})";

TEST(WorldEdges, EveryBodyAndStaticBoxIsEdgedAndThePlaneIsNot) {
  std::string pattern = (fs::temp_directory_path() / "odelab-world-edges-XXXXXX").string();
  ASSERT_NE(mkdtemp(pattern.data()), nullptr);
  const fs::path folder = pattern;
  world::WorldFileScene scene(world::worldFromJson(STACK));
  RunOptions options;
  options.headless = true;
  options.outDir = folder.string();
  scene.initialize(options);
  int edged = 0;
  for (const auto& object : scene.run().objects()) {
    if (object->shape() == Shape::Plane) {
      EXPECT_FALSE(object->edged) << "the ground plane has no edges to draw";
      continue;
    }
    EXPECT_TRUE(object->edged) << "a world body drawn without edges";
    ++edged;
  }
  EXPECT_EQ(edged, 4);  // three bodies and the static box
  scene.shutdown();
  std::error_code ignored;
  fs::remove_all(folder, ignored);
}

}  // namespace
