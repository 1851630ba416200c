// DoneRuns: the runs a resumed sweep skips.
#include <gtest/gtest.h>

#include "sweep/done_runs.hpp"

namespace fsweep {
namespace {

TEST(DoneRuns, EachRowSkipsOneRun) {
  DoneRuns d;
  d.add(7, 3);
  d.add(7, 9);
  d.add(2, 1);
  d.seal();
  EXPECT_TRUE(d.contains(7, 9));
  EXPECT_FALSE(d.contains(7, 4));
  EXPECT_EQ(d.untaken(), 3U);
  EXPECT_TRUE(d.take(7));
  EXPECT_TRUE(d.take(7));
  EXPECT_FALSE(d.take(7));
  EXPECT_TRUE(d.take(2));
  EXPECT_FALSE(d.take(5));
  EXPECT_EQ(d.untaken(), 0U);
}

TEST(DoneRuns, ParsesKeysAndIndices) {
  EXPECT_EQ(parse_run_key("00000000000000ff"), 255U);
  EXPECT_FALSE(parse_run_key("ff"));
  EXPECT_FALSE(parse_run_key("00000000000000fg"));
  EXPECT_EQ(parse_run_index("42"), 42U);
  EXPECT_FALSE(parse_run_index(""));
  EXPECT_FALSE(parse_run_index("4x"));
}

}  // namespace
}  // namespace fsweep
