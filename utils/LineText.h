#pragma once

// The outputs' line format (Test2_output.txt, the run log, the lines a
// program prints before its metrics): one record a line, "# key: value"
// comments, and a last "# complete" or "# incomplete" line that a reader
// trusts. Text a user or an engine gave (a world's title, an engine's error)
// must not start a line of its own: this is the one function that makes such
// text one line, for every writer of the format.

#include <string>

namespace odelab {

// `text` with every control character written out: a line feed as "\n", a
// carriage return as "\r", any other byte below 0x20 but the tab, and 0x7f,
// as "\xHH". Everything else (UTF-8, tabs) is kept as it is.
std::string lineText(const std::string& text);

}  // namespace odelab
