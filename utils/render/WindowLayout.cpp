#include "WindowLayout.h"

#include <algorithm>

namespace odelab {

namespace {

// The panel: 18 text lines wide, narrowed to a quarter of a small window
// but never below 14 lines; its margin to the window's edges.
constexpr int PANEL_LINES = 18, PANEL_LEAST_LINES = 14, PANEL_MARGIN = 10;
constexpr double PANEL_MOST_SHARE = 0.25;

}  // namespace

int textPixelsFor(int requested, int windowHeight) {
  return requested > 0 ? requested : std::min(28, std::max(12, windowHeight / 45));
}

int panelCoveredWidth(int windowWidth, int textPixels) {
  const double width = std::clamp(PANEL_MOST_SHARE * windowWidth, static_cast<double>(PANEL_LEAST_LINES * textPixels),
                                  static_cast<double>(PANEL_LINES * textPixels));
  return static_cast<int>(width) + 2 * PANEL_MARGIN;
}

void insertGhostLine(std::vector<std::string>& hud, std::vector<bool>& oneRow, const std::string& line) {
  const long at = std::min<long>(1, static_cast<long>(hud.size()));
  hud.insert(hud.begin() + at, line);
  oneRow.resize(hud.size() - 1, false);
  oneRow.insert(oneRow.begin() + at, false);
}

void insertCompareLines(std::vector<std::string>& hud, std::vector<bool>& oneRow, const std::string& timing,
                        const std::string& layout) {
  const long at = std::min<long>(3, static_cast<long>(hud.size()));
  hud.insert(hud.begin() + at, {timing, layout});
  oneRow.resize(hud.size() - 2, false);
  oneRow.insert(oneRow.begin() + at, {false, false});
}

std::string compareLayoutLine(bool merged) {
  return merged ? "merged: others outlined 5 mm/1 deg off ODE (M views)" : "a view per engine (M merged)";
}

int hudTotalTextWidth(int viewportWidth) { return std::max(80, viewportWidth - 2 * HUD_MARGIN) - 2 * HUD_PADDING; }

int hudColumnGap() { return 2 * HUD_PADDING + HUD_MARGIN; }

HudColumns hudColumns(const std::vector<std::string>& lines, int viewportWidth, int maxHeight, int lineSkip,
                      const TextWidth& width, const std::vector<bool>& oneRow, std::vector<size_t>* firstLines) {
  const int maxRows = std::max(1, (maxHeight - 2 * HUD_PADDING) / std::max(1, lineSkip));
  HudColumns out;
  out.columns = spreadOverColumns(lines, hudTotalTextWidth(viewportWidth), hudColumnGap(), maxRows, MAX_HUD_COLUMNS,
                                  width, Wrap::Items, firstLines, oneRow);
  const int count = std::max<int>(1, static_cast<int>(out.columns.size()));
  out.textWidth = (hudTotalTextWidth(viewportWidth) - (count - 1) * hudColumnGap()) / count;
  return out;
}

}  // namespace odelab
