// Numbers typed into the control panel: read by the command line's own
// validators, so a decimal comma or a hexadecimal number is refused with a
// reason rather than read as something else.
#include <gtest/gtest.h>

#include "TypedNumber.h"

namespace odelab {
namespace {

TEST(TypedNumber, AcceptsWhatTheCommandLineAccepts) {
  double value = -1;
  EXPECT_EQ(readTypedNumber("0.002", 1e-6, 0.1, false, value), "");
  EXPECT_DOUBLE_EQ(value, 0.002);
  EXPECT_EQ(readTypedNumber(" 1e-5 ", 0, 1, false, value), "");
  EXPECT_DOUBLE_EQ(value, 1e-5);
  EXPECT_EQ(readTypedNumber("020", 1, 10000, true, value), "");  // decimal: 20, not octal 16
  EXPECT_DOUBLE_EQ(value, 20);
}

TEST(TypedNumber, RefusesCommasHexadecimalAndTheOutOfRange) {
  double value = 7;
  EXPECT_EQ(readTypedNumber("0,002", 1e-6, 0.1, false, value), "'0,002' is not a number");
  EXPECT_EQ(readTypedNumber("1,5", 1, 10000, true, value), "'1,5' is not a decimal whole number");
  EXPECT_EQ(readTypedNumber("0x10", 1, 10000, true, value), "'0x10' is not a decimal whole number");
  EXPECT_EQ(readTypedNumber("0x10", 0, 100, false, value), "'0x10' is not a number");
  EXPECT_NE(readTypedNumber("2", 1e-6, 0.1, false, value), "");
  EXPECT_NE(readTypedNumber("nan", 0, 1, false, value), "");
  EXPECT_NE(readTypedNumber("", 0, 1, false, value), "");
  EXPECT_EQ(value, 7);  // a refused text leaves the value alone
}

}  // namespace
}  // namespace odelab
