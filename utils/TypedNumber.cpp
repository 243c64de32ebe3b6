#include "TypedNumber.h"

#include <cmath>

#include "CommandLine.h"

namespace odelab {

std::string readTypedNumber(const std::string& typed, double min, double max, bool integer, double& value) {
  // Spaces around a typed number are the field's, not the number's.
  const size_t first = typed.find_first_not_of(' ');
  std::string text = first == std::string::npos ? std::string() : typed.substr(first, typed.find_last_not_of(' ') - first + 1);
  if (text.empty()) return "nothing typed";
  std::string why;
  if (integer) {
    why = cli::decimalInteger()(text);
    if (why.empty())
      why = cli::integerRange(static_cast<int>(std::ceil(min)), static_cast<int>(std::floor(max)))(text);
  } else {
    why = cli::finiteRange(min, max)(text);
  }
  if (!why.empty()) return why;
  CLI::detail::lexical_cast(text, value);
  return {};
}

}  // namespace odelab
