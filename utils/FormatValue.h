#pragma once

#include <iomanip>
#include <sstream>
#include <string>

namespace odelab {

// A setting or measurement for people to read: six significant digits.
inline std::string formatValue(double value) {
  std::ostringstream out;
  out << std::setprecision(6) << value;
  return out.str();
}

}  // namespace odelab
