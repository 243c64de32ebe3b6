#pragma once

#include <string>
#include <vector>

#include "TextColumns.h"

namespace odelab {

// Where the window's parts go and how big its text is: one rule each, read
// by the window (HudText, ControlPanel, FrameLoop) and by the checks of what
// fits at a window size (checks/unit/test_hud_fit.cpp). Pure arithmetic and
// strings; the width of a text in pixels comes from the caller (the font).

constexpr int HUD_PADDING = 8;       // pixels between a text box's edge and its text
constexpr int HUD_MARGIN = 10;       // pixels between the window's corner and the HUD box
constexpr int HUD_MAX_PERCENT = 22;  // of the window's height, the HUD strip's most
constexpr int MAX_HUD_COLUMNS = 3;

// Text height in pixels: `requested`, or when 0 one 45th of the window's
// height within [12, 28] (16 at 720 rows).
int textPixelsFor(int requested, int windowHeight);

// The width the control panel takes from the right of a window `windowWidth`
// wide with text `textPixels` high, its margins included (while it shows).
int panelCoveredWidth(int windowWidth, int textPixels);

// A world file's ghost line (GhostDraw::hudLine) put after the scene's
// headline, so it shows near the top in the compact HUD as in the full one.
void insertGhostLine(std::vector<std::string>& hud, std::vector<bool>& oneRow, const std::string& line);

// A compare window's two HUD lines (each engine's ms/step, the layout and
// its key) put after the scene's first three lines, with their oneRow marks:
// both are broken between items rather than cut, so every engine's figure
// shows however narrow the strip.
void insertCompareLines(std::vector<std::string>& hud, std::vector<bool>& oneRow, const std::string& timing,
                        const std::string& layout);

// A compare window's HUD line for its layout and the key that changes it.
std::string compareLayoutLine(bool merged);

// The HUD strip's columns for a viewport `viewportWidth` x `maxHeight`
// pixels of text `lineSkip` rows apart, as spreadOverColumns lays them out,
// and the width each column's text has (its box's padding taken off).
struct HudColumns {
  std::vector<std::vector<std::string>> columns;
  int textWidth = 0;
};
int hudTotalTextWidth(int viewportWidth);  // every column's text and the gaps between them
int hudColumnGap();
HudColumns hudColumns(const std::vector<std::string>& lines, int viewportWidth, int maxHeight, int lineSkip,
                      const TextWidth& width, const std::vector<bool>& oneRow = {},
                      std::vector<size_t>* firstLines = nullptr);

}  // namespace odelab
