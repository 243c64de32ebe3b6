#pragma once

#include <functional>
#include <string>
#include <vector>

namespace odelab {

// Text laid out for a box of limited width and height: lines broken between
// items, then spread over side-by-side columns. Pure string work; the width
// of a text in pixels comes from the caller (the font).
using TextWidth = std::function<int(const std::string&)>;

// Breaks every line wider than maxWidth pixels: first between its items
// (parts separated by three spaces, as the HUD writes them), then, for an
// item wider still, between words. Continuation lines are indented by three
// spaces so they read as part of the line above. maxWidth <= 0: no limit.
std::vector<std::string> wrapItems(const std::vector<std::string>& lines, int maxWidth, const TextWidth& width);

// Breaks every line wider than maxWidth pixels between words, continuing
// under its text column: a help line "F6           QuickStep iterations ..."
// goes on under "QuickStep" (the text after the first run of two or more
// spaces near the line's start; three spaces in when there is none).
std::vector<std::string> wrapHanging(const std::vector<std::string>& lines, int maxWidth, const TextWidth& width);

// How spreadOverColumns breaks a line too wide for its column.
enum class Wrap { Items, Hanging };

// `line` cut at a character so that it and "..." fit in maxWidth pixels;
// unchanged when it fits.
std::string cutToWidth(const std::string& line, int maxWidth, const TextWidth& width);

// The lines in the fewest columns (at most maxColumns) of width
// (totalWidth - gaps) / columns whose tallest holds at most maxRows lines;
// when none does, the count that gives the shortest. A line and its continuation
// lines stay in one column, and columns are filled in reading order.
// `firstLines`, when given, receives the index in `lines` of each column's
// first line (for columnsFrom). A line whose entry in `oneRow` is true is
// not broken but cut to one row (cutToWidth): a line whose text comes and
// goes takes one row, whatever it says.
std::vector<std::vector<std::string>> spreadOverColumns(const std::vector<std::string>& lines, int totalWidth,
                                                        int gap, int maxRows, int maxColumns,
                                                        const TextWidth& width, Wrap wrap = Wrap::Items,
                                                        std::vector<size_t>* firstLines = nullptr,
                                                        const std::vector<bool>& oneRow = {});

// The lines in firstLines.size() columns as spreadOverColumns makes them,
// but each column starting at the line firstLines names (ascending; a start
// past the end leaves its column empty): a layout kept while lines change,
// so no item moves to another column.
std::vector<std::vector<std::string>> columnsFrom(const std::vector<std::string>& lines,
                                                  const std::vector<size_t>& firstLines, int totalWidth, int gap,
                                                  const TextWidth& width, Wrap wrap = Wrap::Items,
                                                  const std::vector<bool>& oneRow = {});

// Columns side by side as one block of lines, for a monospaced font: each
// column padded with spaces to its longest line (counted in characters, not
// bytes), then `gap` spaces.
std::vector<std::string> joinColumns(const std::vector<std::vector<std::string>>& columns, int gap);

}  // namespace odelab
