// CompareLanes, the compare window's lockstep: a scene that follows another
// takes every input the leading scene is given, at the same step, and
// follows it forward, back through a rewind, and through R. Two ODE scenes
// of test5 (plates dropped with N) stand for the lead and an engine's scene:
// following, they must stay in the same state bit for bit.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "CompareLanes.h"
#include "SceneRegistry.h"

namespace {

using namespace odelab;
namespace fs = std::filesystem;

struct Folder {
  fs::path path;
  Folder() {
    std::string pattern = (fs::temp_directory_path() / "odelab-compare-lanes-XXXXXX").string();
    path = mkdtemp(pattern.data());
  }
  ~Folder() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

std::unique_ptr<AbstractWindow> test5(const fs::path& folder) {
  const SceneEntry* entry = findScene("test5");
  if (!entry) throw std::runtime_error("no scene test5");
  std::unique_ptr<AbstractWindow> scene = entry->make();
  RunOptions options;
  options.headless = true;
  options.outDir = folder.string();
  scene->initialize(options);
  return scene;
}

// `steps` steps of the lead, each followed as a frame of one step would be.
void stepBoth(AbstractWindow& lead, CompareLanes& lanes, int steps) {
  for (int i = 0; i < steps; ++i) {
    ASSERT_TRUE(lead.stepOnce());
    lanes.follow(0.0, 1);
  }
}

int knobNamed(const AbstractWindow& scene, const std::string& name) {
  const auto& knobs = scene.tuning().knobs();
  for (size_t i = 0; i < knobs.size(); ++i)
    if (knobs[i].name == name) return static_cast<int>(i);
  return -1;
}

TEST(CompareLanes, AFollowerTakesEveryInputAtTheLeadsStep) {
  Folder leadFolder, followerFolder;
  std::unique_ptr<AbstractWindow> lead = test5(leadFolder.path);
  std::unique_ptr<AbstractWindow> follower = test5(followerFolder.path);
  {
    CompareLanes lanes(*lead, {{"copy", follower.get()}});
    stepBoth(*lead, lanes, 100);
    const int before = follower->run().bodyCount();
    ASSERT_TRUE(lead->handleKey(SDLK_n, false));  // a plate dropped at step 100
    EXPECT_EQ(follower->run().bodyCount(), before + 1);
    stepBoth(*lead, lanes, 50);
    const int erp = knobNamed(*lead, "erp");
    ASSERT_GE(erp, 0);
    lead->changeKnob(erp, 0.5);  // the panel, at step 150
    stepBoth(*lead, lanes, 100);
    EXPECT_EQ(follower->run().steps(), 250);
    EXPECT_EQ(follower->run().bodyCount(), lead->run().bodyCount());
    EXPECT_EQ(follower->tuning().settings().erp, 0.5);
    EXPECT_EQ(follower->run().stateHash(), lead->run().stateHash());

    // A rewind before the panel's change: the follower replays its own record.
    lead->replayTo(120);
    lanes.follow(0.0, 0);
    EXPECT_EQ(follower->run().steps(), 120);
    EXPECT_EQ(follower->run().stateHash(), lead->run().stateHash());
    stepBoth(*lead, lanes, 80);
    EXPECT_EQ(follower->run().stateHash(), lead->run().stateHash());

    // R starts both again.
    ASSERT_TRUE(lead->handleKey(SDLK_r, false));
    lanes.follow(0.0, 0);
    EXPECT_EQ(follower->run().steps(), 0);
    stepBoth(*lead, lanes, 60);
    EXPECT_EQ(follower->run().stateHash(), lead->run().stateHash());
    EXPECT_TRUE(lanes.lanes()[1].failure.empty());
  }
  follower->shutdown();
  lead->shutdown();
}

}  // namespace
