// The compare window's HUD with every engine a program can run fits its
// strip at 1280x720 and 1024x768 with the panel open: every line within its
// column in the HUD's own font at the size the window gives it, and every
// engine's ms/step figure whole on one row. Measured with the window's own
// rules (WindowLayout: text size, panel width, the strip's columns) and the
// HUD's font (SDL2_ttf needs no display), on test2's own HUD lines.

#include <gtest/gtest.h>

#include <SDL2/SDL_ttf.h>
#include <stdlib.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "AbstractWindow.h"
#include "Adapters.h"
#include "CompareLanes.h"
#include "ResourcePaths.h"
#include "SceneRegistry.h"
#include "render/WindowLayout.h"
#include "world/EngineCatalog.h"

namespace {

using namespace odelab;
namespace fs = std::filesystem;

struct FontCloser {
  void operator()(TTF_Font* font) const { TTF_CloseFont(font); }
};

std::vector<std::string> everyEngine() {
  std::vector<std::string> names{"ode"};
  for (const world::EngineInfo& info : engines::catalog().list()) names.push_back(info.name);
  return names;
}

struct Window {
  int width, height;
};

class HudFit : public ::testing::TestWithParam<Window> {
 protected:
  static void SetUpTestSuite() { ASSERT_EQ(TTF_Init(), 0) << TTF_GetError(); }
  static void TearDownTestSuite() { TTF_Quit(); }

  // test2's compact HUD lines as its window shows them (paused or running).
  static std::vector<std::string> test2Hud(bool paused) {
    // A folder of this run's own: CTest runs each case as its own process, side by side.
    std::string pattern = (fs::temp_directory_path() / "odelab-hud-fit-XXXXXX").string();
    if (!mkdtemp(pattern.data())) {
      ADD_FAILURE() << "cannot make a folder like " << pattern;
      return {};
    }
    const fs::path folder = pattern;
    const SceneEntry* entry = findScene("test2");
    EXPECT_NE(entry, nullptr);
    std::unique_ptr<AbstractWindow> scene = entry->make();
    RunOptions options;
    options.headless = true;
    options.outDir = folder.string();
    scene->initialize(options);
    for (int i = 0; i < 100; ++i) scene->stepOnce();
    scene->session().time().setPaused(paused);
    std::vector<std::string> lines = scene->hudLines();
    scene->shutdown();
    std::error_code ignored;
    fs::remove_all(folder, ignored);
    return lines;
  }

  // Every engine's lane, each with the widest figure its ms/step can read
  // ("0.0071": two significant figures below 0.01 ms) or "stopped".
  static std::vector<CompareLanes::Lane> lanes(bool stopped) {
    std::vector<CompareLanes::Lane> all;
    for (const std::string& engine : everyEngine()) {
      CompareLanes::Lane lane;
      lane.engine = engine;
      lane.msPerStep = 0.0071;
      if (stopped && engine != "ode") lane.failure = "blew up";
      all.push_back(lane);
    }
    all.back().msPerStep = 0.0093;  // the slowest, for the line that names it
    return all;
  }

  void expectFits(const std::vector<std::string>& scene, const std::vector<CompareLanes::Lane>& lanes, bool behind,
                  bool merged) {
    const Window window = GetParam();
    const int pixels = textPixelsFor(0, window.height);
    const std::string fontPath = findFont("").found;
    ASSERT_FALSE(fontPath.empty()) << "no HUD font found";
    std::unique_ptr<TTF_Font, FontCloser> font(TTF_OpenFont(fontPath.c_str(), pixels));
    ASSERT_TRUE(font) << TTF_GetError();
    const TextWidth width = [&font](const std::string& text) {
      int w = 0, h = 0;
      return TTF_SizeUTF8(font.get(), text.c_str(), &w, &h) == 0 ? w : 0;
    };
    std::vector<std::string> hud = scene;
    std::vector<bool> oneRow(hud.size(), false);
    const std::string timing = CompareLanes::timingLine(lanes, behind);
    insertCompareLines(hud, oneRow, timing, compareLayoutLine(merged));
    // The scene's area: the window less the panel's column on the right.
    const int viewport = window.width - panelCoveredWidth(window.width, pixels);
    const HudColumns layout = hudColumns(hud, viewport, window.height * HUD_MAX_PERCENT / 100,
                                         TTF_FontLineSkip(font.get()), width, oneRow);
    const std::string where = std::to_string(window.width) + "x" + std::to_string(window.height) + " (panel open, " +
                              std::to_string(viewport) + " px for the HUD, text " + std::to_string(pixels) + " px)";
    std::string shown;
    for (const std::vector<std::string>& column : layout.columns)
      for (const std::string& line : column) {
        // Wider than its column, the line would be cut with "..." when drawn.
        EXPECT_LE(width(line), layout.textWidth) << where << ": '" << line << "' is cut";
        shown += line + "\n";
      }
    for (const CompareLanes::Lane& lane : lanes) {
      const std::string figure = CompareLanes::timingLine({lane}, false).substr(std::string("ms/step: ").size());
      EXPECT_NE(shown.find(figure), std::string::npos)
          << where << ": '" << figure << "' is not whole on one row of the HUD:\n" << shown;
    }
    if (behind) {
      EXPECT_NE(shown.find("behind real time"), std::string::npos) << where << ":\n" << shown;
    }
    EXPECT_NE(shown.find(compareLayoutLine(merged)), std::string::npos) << where << ":\n" << shown;
  }
};

TEST_P(HudFit, PausedEveryEngineFigureShows) { expectFits(test2Hud(true), lanes(false), false, false); }

TEST_P(HudFit, RunningBehindRealTimeMergedEveryEngineFigureShows) {
  expectFits(test2Hud(false), lanes(false), true, true);
}

TEST_P(HudFit, EveryEngineStoppedStillShows) { expectFits(test2Hud(true), lanes(true), false, true); }

INSTANTIATE_TEST_SUITE_P(WindowSizes, HudFit, ::testing::Values(Window{1280, 720}, Window{1024, 768}),
                         [](const ::testing::TestParamInfo<Window>& info) {
                           return std::to_string(info.param.width) + "x" + std::to_string(info.param.height);
                         });

}  // namespace
