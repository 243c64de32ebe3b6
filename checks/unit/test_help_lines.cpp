// The help overlay (H) lists every key of the scene: it is built from the
// same table that dispatches the keys, so a binding a scene adds shows too.
#include <gtest/gtest.h>

#include "AbstractWindow.h"

namespace {

using namespace odelab;

class KeyScene : public AbstractWindow {
 public:
  KeyScene() : AbstractWindow(WorldSettings{}) {
    identify("unit", "keys");
    bindKey(SDLK_b, "B", "spawn something", [](int) {});
    bindKey(SDLK_q, "Q", "next collision space", [](int) {});
    bindViewKey(SDLK_k, "K", "a view-only key", [](int) {});
  }

 protected:
  void buildScene() override {}
};

TEST(HelpLines, ListEveryBinding) {
  KeyScene scene;
  const std::vector<std::string> lines = scene.helpLines();
  ASSERT_FALSE(scene.keys().bindings().empty());
  for (const KeyBinding& binding : scene.keys().bindings()) {
    bool found = false;
    for (const std::string& line : lines)
      found = found || (line.rfind(binding.keyName + " ", 0) == 0 && line.find(binding.description) != std::string::npos);
    EXPECT_TRUE(found) << "no help line for key " << binding.keyName << " (" << binding.description << ")";
  }
}

TEST(HelpLines, NameTheMouseAndTheLabKeys) {
  KeyScene scene;
  const std::vector<std::string> lines = scene.helpLines();
  auto mentions = [&](const std::string& start) {
    for (const std::string& line : lines)
      if (line.rfind(start, 0) == 0) return true;
    return false;
  };
  EXPECT_TRUE(mentions("left mouse"));
  EXPECT_TRUE(mentions("W/S/A/D"));
  EXPECT_TRUE(mentions("mouse wheel"));
  for (const char* key : {"P ", "O ", "- ", "= ", ", ", ". ", "H ", "L ", "C ", "J ", "X ", "V ", "F12 ", "F9 ", "B ", "Q ", "K "})
    EXPECT_TRUE(mentions(key)) << key;
}

}  // namespace
