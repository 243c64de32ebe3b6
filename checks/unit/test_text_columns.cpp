// Text layout of the HUD and the help: lines break between items (parts
// separated by three spaces) before they break between words, and columns
// keep a line with its continuation lines.
#include <gtest/gtest.h>

#include "render/TextColumns.h"

namespace odelab {
namespace {

// One pixel a character: widths are character counts.
int characters(const std::string& text) { return static_cast<int>(text.size()); }

TEST(TextColumns, BreaksBetweenItemsNotInsideThem) {
  const std::vector<std::string> lines = wrapItems({"FPS 60 (paced)   real-time x1.00   H / help"}, 20, characters);
  EXPECT_EQ(lines, (std::vector<std::string>{"FPS 60 (paced)", "   real-time x1.00", "   H / help"}));
}

TEST(TextColumns, BreaksAnItemWiderThanTheBoxBetweenWords) {
  const std::vector<std::string> lines = wrapItems({"a bb ccc dddd eeeee"}, 10, characters);
  for (const std::string& line : lines) EXPECT_LE(line.size(), 10u) << line;
  EXPECT_EQ(lines.front(), "a bb ccc");
}

TEST(TextColumns, LinesThatFitStayWhole) {
  const std::vector<std::string> lines{"short", "   indented help line"};
  EXPECT_EQ(wrapItems(lines, 80, characters), lines);
}

TEST(TextColumns, SpreadsOverColumnsOnlyWhenTooTall) {
  const std::vector<std::string> lines{"one", "two", "three", "four"};
  EXPECT_EQ(spreadOverColumns(lines, 100, 4, 10, 3, characters).size(), 1u);
  const auto columns = spreadOverColumns(lines, 100, 4, 2, 3, characters);
  ASSERT_EQ(columns.size(), 2u);
  EXPECT_EQ(columns[0], (std::vector<std::string>{"one", "two"}));
  EXPECT_EQ(columns[1], (std::vector<std::string>{"three", "four"}));
}

TEST(TextColumns, JoinsColumnsPaddedToTheirWidestLine) {
  EXPECT_EQ(joinColumns({{"ab", "a"}, {"x"}}, 2), (std::vector<std::string>{"ab  x", "a"}));
}

}  // namespace
}  // namespace odelab

namespace odelab {
namespace {

TEST(TextColumns, HelpLinesContinueUnderTheirTextColumn) {
  const std::vector<std::string> lines =
      wrapHanging({"F6           QuickStep iterations up (Shift: down)"}, 32, characters);
  EXPECT_EQ(lines, (std::vector<std::string>{"F6           QuickStep", "             iterations up", "             (Shift: down)"}));
}

// A line added at the end (a notice) re-balances a fresh spread, moving a
// line from the second column to the first; the layout kept from before
// (columnsFrom with the first spread's starts) leaves every line where it was.
TEST(TextColumns, KeptColumnsDoNotMoveLinesWhenOneIsAdded) {
  const std::vector<std::string> before{"a1", "a2", "b1", "b2"};
  std::vector<size_t> starts;
  const auto first = spreadOverColumns(before, 100, 2, 2, 2, characters, Wrap::Items, &starts);
  ASSERT_EQ(first, (std::vector<std::vector<std::string>>{{"a1", "a2"}, {"b1", "b2"}}));
  ASSERT_EQ(starts, (std::vector<size_t>{0, 2}));
  std::vector<std::string> after = before;
  after.push_back("notice");
  const auto respread = spreadOverColumns(after, 100, 2, 2, 2, characters);
  EXPECT_EQ(respread.front(), (std::vector<std::string>{"a1", "a2", "b1"}));  // b1 changed columns
  const auto kept = columnsFrom(after, starts, 100, 2, characters);
  EXPECT_EQ(kept, (std::vector<std::vector<std::string>>{{"a1", "a2"}, {"b1", "b2", "notice"}}));
}

// A line marked one-row is cut with "..." rather than broken over rows.
TEST(TextColumns, OneRowLinesAreCutNotBroken) {
  const std::string notice = "a notice longer than the column   so it would wrap over two rows";
  const auto columns =
      spreadOverColumns({"short", notice}, 50, 2, 10, 1, characters, Wrap::Items, nullptr, {false, true});
  ASSERT_EQ(columns.size(), 1u);
  EXPECT_EQ(columns[0], (std::vector<std::string>{"short", notice.substr(0, 47) + "..."}));
  EXPECT_EQ(cutToWidth("fits", 12, characters), "fits");
}

}  // namespace
}  // namespace odelab
