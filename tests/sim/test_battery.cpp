#include <gtest/gtest.h>

#include "sim/battery.hpp"

namespace fsweep {
namespace {

TEST(Battery, RangeIsChargeOverEnergyPerMetre) {
  Battery b(100.0, 2.0);  // 2 energy units per metre of straight travel
  EXPECT_DOUBLE_EQ(b.remaining_range_m(), 50.0);
  ASSERT_TRUE(b.draw(30.0, 10.0));  // 3 per metre so far (turns included)
  EXPECT_DOUBLE_EQ(b.level(), 70.0);
  EXPECT_DOUBLE_EQ(b.remaining_range_m(), 70.0 / 3.0);
}

TEST(Battery, RefusesADrawBeyondTheCharge) {
  Battery b(10.0, 1.0);
  EXPECT_FALSE(b.draw(11.0, 11.0));
  EXPECT_DOUBLE_EQ(b.level(), 10.0);
  EXPECT_TRUE(b.draw(10.0, 10.0));
  EXPECT_DOUBLE_EQ(b.level(), 0.0);
  b.recharge();
  EXPECT_TRUE(b.full());
}

TEST(Battery, UnlimitedNeverRunsOut) {
  Battery b(std::numeric_limits<double>::infinity(), 1.0);
  EXPECT_TRUE(b.unlimited());
  EXPECT_TRUE(b.draw(1e12, 1e12));
  EXPECT_EQ(b.remaining_range_m(), std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace fsweep
