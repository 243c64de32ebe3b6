#include "TextColumns.h"

#include <algorithm>

namespace odelab {

namespace {

const std::string ITEM_SEPARATOR = "   ";
const std::string INDENT = "   ";

// Splits at `separator`, dropping empty parts (runs of separators).
std::vector<std::string> split(const std::string& line, const std::string& separator) {
  std::vector<std::string> parts;
  size_t start = 0;
  while (start <= line.size()) {
    size_t end = line.find(separator, start);
    if (end == std::string::npos) end = line.size();
    if (end > start) parts.push_back(line.substr(start, end - start));
    start = end + separator.size();
  }
  return parts;
}

// Greedy packing of `parts` joined by `joiner` into lines of at most maxWidth;
// a part that does not fit alone is left on a line of its own (the caller
// breaks it further).
std::vector<std::string> pack(const std::vector<std::string>& parts, const std::string& joiner,
                              const std::string& firstPrefix, int maxWidth, const TextWidth& width,
                              const std::string& continuation = INDENT) {
  std::vector<std::string> out;
  std::string current;
  for (const std::string& part : parts) {
    const std::string prefix = out.empty() && current.empty() ? firstPrefix : continuation;
    const std::string joined = current.empty() ? prefix + part : current + joiner + part;
    if (current.empty() || width(joined) <= maxWidth) {
      current = joined;
    } else {
      out.push_back(current);
      current = continuation + part;
    }
  }
  if (!current.empty()) out.push_back(current);
  return out;
}

// Characters in UTF-8 text: every byte but continuation bytes.
size_t characters(const std::string& text) {
  return static_cast<size_t>(
      std::count_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

// Every line that does not fit in maxWidth replaced by what `wrap` makes of it.
std::vector<std::string> wrapEach(const std::vector<std::string>& lines, int maxWidth, const TextWidth& width,
                                  const std::function<void(const std::string&, std::vector<std::string>&)>& wrap) {
  if (maxWidth <= 0) return lines;
  std::vector<std::string> out;
  for (const std::string& line : lines) {
    if (line.empty() || width(line) <= maxWidth)
      out.push_back(line);
    else
      wrap(line, out);
  }
  return out;
}

}  // namespace

std::string cutToWidth(const std::string& line, int maxWidth, const TextWidth& width) {
  if (width(line) <= maxWidth) return line;
  std::string cut = line;
  while (!cut.empty() && width(cut + "...") > maxWidth) {
    // Drop one whole UTF-8 character: its continuation bytes, then its lead byte.
    while (!cut.empty() && (static_cast<unsigned char>(cut.back()) & 0xC0) == 0x80) cut.pop_back();
    if (!cut.empty()) cut.pop_back();
  }
  return cut + "...";
}

namespace {

int columnWidthFor(int totalWidth, int gap, int count) { return std::max(40, (totalWidth - (count - 1) * gap) / count); }

}  // namespace

std::vector<std::string> wrapItems(const std::vector<std::string>& lines, int maxWidth, const TextWidth& width) {
  return wrapEach(lines, maxWidth, width, [&](const std::string& line, std::vector<std::string>& out) {
    // Keep a line's own leading spaces on its first piece.
    const std::string leading = line.substr(0, std::min(line.find_first_not_of(' '), line.size()));
    for (const std::string& piece : pack(split(line.substr(leading.size()), ITEM_SEPARATOR), ITEM_SEPARATOR,
                                         leading, maxWidth, width)) {
      if (width(piece) <= maxWidth) {
        out.push_back(piece);
        continue;
      }
      // One item wider than the box: break it between words.
      const size_t start = std::min(piece.find_first_not_of(' '), piece.size());
      for (const std::string& part : pack(split(piece.substr(start), " "), " ", piece.substr(0, start), maxWidth, width))
        out.push_back(part);
    }
  });
}

std::vector<std::string> wrapHanging(const std::vector<std::string>& lines, int maxWidth, const TextWidth& width) {
  // How far in the text column of an aligned line may start.
  const size_t NEAR_START = 20;
  return wrapEach(lines, maxWidth, width, [&](const std::string& line, std::vector<std::string>& out) {
    const size_t gap = line.find("  ");
    size_t column = gap != std::string::npos && gap < NEAR_START ? line.find_first_not_of(' ', gap) : 0;
    if (column == std::string::npos) column = 0;
    const std::string hang(column > 0 ? column : INDENT.size(), ' ');
    for (const std::string& part :
         pack(split(line.substr(column), " "), " ", line.substr(0, column), maxWidth, width, hang))
      out.push_back(part);
  });
}

namespace {

std::vector<std::string> wrapOne(const std::string& line, int columnWidth, const TextWidth& width, Wrap wrap,
                                 bool oneRow) {
  if (oneRow) return {cutToWidth(line, columnWidth, width)};
  return wrap == Wrap::Items ? wrapItems({line}, columnWidth, width) : wrapHanging({line}, columnWidth, width);
}

}  // namespace

std::vector<std::vector<std::string>> spreadOverColumns(const std::vector<std::string>& lines, int totalWidth,
                                                        int gap, int maxRows, int maxColumns,
                                                        const TextWidth& width, Wrap wrap,
                                                        std::vector<size_t>* firstLines, const std::vector<bool>& oneRow) {
  std::vector<std::vector<std::string>> best;
  std::vector<size_t> bestStarts;
  size_t bestRows = 0;
  for (int count = 1; count <= std::max(1, maxColumns); ++count) {
    const int columnWidth = columnWidthFor(totalWidth, gap, count);
    // Each line with its continuation lines, kept together.
    std::vector<std::vector<std::string>> groups;
    size_t rows = 0;
    for (size_t i = 0; i < lines.size(); ++i) {
      groups.push_back(wrapOne(lines[i], columnWidth, width, wrap, i < oneRow.size() && oneRow[i]));
      rows += groups.back().size();
    }
    const size_t perColumn = (rows + static_cast<size_t>(count) - 1) / static_cast<size_t>(count);
    std::vector<std::vector<std::string>> columns(1);
    std::vector<size_t> starts{0};
    for (size_t i = 0; i < groups.size(); ++i) {
      const auto& group = groups[i];
      if (!columns.back().empty() && columns.back().size() + group.size() > perColumn &&
          static_cast<int>(columns.size()) < count) {
        columns.emplace_back();
        starts.push_back(i);
      }
      columns.back().insert(columns.back().end(), group.begin(), group.end());
    }
    size_t tallest = 0;
    for (const auto& column : columns) tallest = std::max(tallest, column.size());
    // Fewer columns while they fit; past the height, whichever is shortest.
    if (best.empty() || tallest < bestRows) {
      best = columns;
      bestStarts = starts;
      bestRows = tallest;
    }
    if (static_cast<int>(tallest) <= maxRows) break;
  }
  if (firstLines) *firstLines = bestStarts;
  return best;
}

std::vector<std::vector<std::string>> columnsFrom(const std::vector<std::string>& lines,
                                                  const std::vector<size_t>& firstLines, int totalWidth, int gap,
                                                  const TextWidth& width, Wrap wrap, const std::vector<bool>& oneRow) {
  const int count = std::max(1, static_cast<int>(firstLines.size()));
  const int columnWidth = columnWidthFor(totalWidth, gap, count);
  std::vector<std::vector<std::string>> columns(static_cast<size_t>(count));
  for (size_t c = 0; c < firstLines.size(); ++c) {
    const size_t end = c + 1 < firstLines.size() ? firstLines[c + 1] : lines.size();
    for (size_t i = firstLines[c]; i < std::min(end, lines.size()); ++i) {
      const std::vector<std::string> group = wrapOne(lines[i], columnWidth, width, wrap, i < oneRow.size() && oneRow[i]);
      columns[c].insert(columns[c].end(), group.begin(), group.end());
    }
  }
  return columns;
}

std::vector<std::string> joinColumns(const std::vector<std::vector<std::string>>& columns, int gap) {
  size_t rows = 0;
  for (const auto& column : columns) rows = std::max(rows, column.size());
  std::vector<std::string> out(rows);
  for (size_t c = 0; c < columns.size(); ++c) {
    size_t wide = 0;
    for (const std::string& line : columns[c]) wide = std::max(wide, characters(line));
    for (size_t r = 0; r < rows; ++r) {
      const std::string line = r < columns[c].size() ? columns[c][r] : std::string();
      if (c + 1 < columns.size())
        out[r] += line + std::string(wide - characters(line) + static_cast<size_t>(gap), ' ');
      else
        out[r] += line;
    }
  }
  for (std::string& line : out) line.erase(line.find_last_not_of(' ') + 1);
  return out;
}

}  // namespace odelab
