#pragma once

#include <string>
#include <vector>

#include "HudText.h"

namespace odelab {

// The help (H): every key and the mouse in columns over the whole window,
// opaque. When even the most columns run past the window's height, the
// list is cut into pages (between lines, never inside one), each ending
// with how to turn it: Page Down / Space and Page Up.
class HelpOverlay {
 public:
  void draw(HudText& text, const std::vector<std::string>& lines, int width, int height);
  // Page Down / Space: +1, Page Up: -1; kept within the pages there are.
  void turn(int pages) { page_ += pages; }
  void close() { page_ = 0; }

  static constexpr int MAX_COLUMNS = 3;

 private:
  void paginate(HudText& text, const std::vector<std::string>& lines, int width, int height);

  TextBlock block_{255};  // opaque: neither the HUD nor the scene shows through
  std::vector<std::vector<std::string>> pages_;  // each page's lines, laid out in columns
  std::vector<std::string> laidOut_;             // the lines the pages were made from
  int laidWidth_ = 0, laidHeight_ = 0, laidLineSkip_ = 0;
  int page_ = 0;
};

}  // namespace odelab
