/// readable_number(): numbers for people, rounded and thousands separated.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/readable_number.hpp"

namespace fsweep {
namespace {

TEST(ReadableNumber, RoundsToSignificantDigitsAndGroupsThousands) {
  EXPECT_EQ(readable_number(1914.4032457428293), "1,914");
  EXPECT_EQ(readable_number(1914.4032457428293, 5), "1,914.4");
  EXPECT_EQ(readable_number(48495.65076287815), "48,496");
  EXPECT_EQ(readable_number(1234567.8), "1,234,568");
  EXPECT_EQ(readable_number(545.0229073212244), "545");
  EXPECT_EQ(readable_number(2.812787310625977), "2.813");
  EXPECT_EQ(readable_number(0.05), "0.05");
  EXPECT_EQ(readable_number(0.000123456), "0.0001235");
  EXPECT_EQ(readable_number(1.234567e-5), "1.235e-05");
  EXPECT_EQ(readable_number(-72.1634), "-72.16");
  EXPECT_EQ(readable_number(9.99996), "10");
}

TEST(ReadableNumber, SignsZeroAndNonFiniteValues) {
  EXPECT_EQ(readable_number(72.1634, 4, Sign::Always), "+72.16");
  EXPECT_EQ(readable_number(-72.1634, 4, Sign::Always), "-72.16");
  EXPECT_EQ(readable_number(0.0, 4, Sign::Always), "0");
  EXPECT_EQ(readable_number(-0.0), "0");
  EXPECT_EQ(readable_number(std::numeric_limits<double>::quiet_NaN()), "");
  EXPECT_EQ(readable_number(std::numeric_limits<double>::infinity(), 4, Sign::Always), "+inf");
  EXPECT_EQ(readable_number(-std::numeric_limits<double>::infinity()), "-inf");
  EXPECT_THROW((void)readable_number(1.0, 0), std::invalid_argument);
}

}  // namespace
}  // namespace fsweep
