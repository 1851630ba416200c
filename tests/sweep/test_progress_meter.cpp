// ProgressMeter: the text of the progress bar and log lines.
#include <gtest/gtest.h>

#include "sweep/progress_meter.hpp"

namespace fsweep {
namespace {

TEST(ProgressMeter, FormatsBarRateAndEta) {
  EXPECT_EQ(ProgressMeter::format(123, 400, "runs", 45.6, true),
            "[#########.....................] 123/400 runs, 45.6 runs/s, ETA 6 s");
  EXPECT_EQ(ProgressMeter::format(400, 400, "runs", 2.5, false), "400/400 runs (100.0%), 2.50 runs/s");
  EXPECT_EQ(ProgressMeter::format_duration(192), "3 min 12 s");
  EXPECT_EQ(ProgressMeter::format_duration(7500), "2 h 05 min");
  EXPECT_EQ(ProgressMeter::format_duration(-1), "?");
}

}  // namespace
}  // namespace fsweep
