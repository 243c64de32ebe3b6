#pragma once

#include <iomanip>
#include <sstream>
#include <string>

namespace odelab {

// A setting or measurement for people to read: six significant digits
// unless told otherwise.
inline std::string formatValue(double value, int significantDigits = 6) {
  std::ostringstream out;
  out << std::setprecision(significantDigits) << value;
  return out.str();
}

}  // namespace odelab
