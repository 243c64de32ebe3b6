#pragma once

#include <string>

namespace odelab {

// A number typed into the control panel, checked by the command line's own
// validators (utils/CommandLine): a whole number is decimal only, a real
// number must be finite and within [min, max]; "0,002", "1,5" and "0x10"
// are refused, never read as something else. Returns "" and sets `value`
// when the text is accepted, else the reason (the command line's words).
std::string readTypedNumber(const std::string& text, double min, double max, bool integer, double& value);

}  // namespace odelab
