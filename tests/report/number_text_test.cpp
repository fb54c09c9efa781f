#include <gtest/gtest.h>

#include "report/number_text.h"

namespace maxillo::report {
namespace {

TEST(NumberText, FixedDecimalsAndNoNegativeZero) {
  EXPECT_EQ(fixed(3.14159, 2), "3.14");
  EXPECT_EQ(fixed(10.0, 0), "10");
  EXPECT_EQ(fixed(-0.004, 2), "0.00");  // would print "-0.00"
  EXPECT_EQ(fixed(-0.04, 1), "0.0");
  EXPECT_EQ(fixed(-0.006, 2), "-0.01");
}

}  // namespace
}  // namespace maxillo::report
