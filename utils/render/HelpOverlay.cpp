#include "HelpOverlay.h"

#include <algorithm>

namespace odelab {

namespace {
const int MARGIN = 10;
}

void HelpOverlay::paginate(HudText& text, const std::vector<std::string>& lines, int width, int height) {
  pages_.clear();
  bool fits = false;
  std::vector<std::string> all = text.inColumns(lines, width, height, MAX_COLUMNS, fits);
  if (fits) {
    pages_.push_back(std::move(all));
    return;
  }
  // The most lines from `start` that fit with a footer line below them.
  const int footerHeight = text.lineSkip();
  for (size_t start = 0; start < lines.size();) {
    std::vector<std::string> page;
    size_t end = start + 1;
    page = text.inColumns({lines.begin() + static_cast<long>(start), lines.begin() + static_cast<long>(end)}, width,
                          height - footerHeight, MAX_COLUMNS, fits);
    for (size_t next = end + 1; next <= lines.size(); ++next) {
      std::vector<std::string> longer = text.inColumns(
          {lines.begin() + static_cast<long>(start), lines.begin() + static_cast<long>(next)}, width,
          height - footerHeight, MAX_COLUMNS, fits);
      if (!fits) break;
      page = std::move(longer);
      end = next;
    }
    pages_.push_back(std::move(page));
    start = end;
  }
  for (size_t i = 0; i < pages_.size(); ++i)
    pages_[i].push_back("page " + std::to_string(i + 1) + " of " + std::to_string(pages_.size()) +
                        ": Page Down or Space for the next, Page Up for the one before");
}

void HelpOverlay::draw(HudText& text, const std::vector<std::string>& lines, int width, int height) {
  const int boxWidth = width - 2 * MARGIN, boxHeight = height - 2 * MARGIN;
  if (lines != laidOut_ || boxWidth != laidWidth_ || boxHeight != laidHeight_ || text.lineSkip() != laidLineSkip_) {
    paginate(text, lines, boxWidth, boxHeight);
    laidOut_ = lines;
    laidWidth_ = boxWidth;
    laidHeight_ = boxHeight;
    laidLineSkip_ = text.lineSkip();
  }
  if (pages_.empty()) return;
  page_ = std::clamp(page_, 0, static_cast<int>(pages_.size()) - 1);
  text.prepare(block_, pages_[static_cast<size_t>(page_)], boxWidth);
  const int x = std::max(MARGIN, (width - block_.width()) / 2);
  const int y = std::max(MARGIN, (height - block_.height()) / 2);
  text.drawAt(block_, x, y, width, height);
}

}  // namespace odelab
