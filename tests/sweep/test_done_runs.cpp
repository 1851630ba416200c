// DoneRuns: the runs a resumed sweep skips.
#include <gtest/gtest.h>

#include "sweep/done_runs.hpp"

namespace fsweep {
namespace {

TEST(DoneRuns, FindsRowsByRunIndex) {
  DoneRuns d;
  d.add(7, 9);
  d.add(7, 3);
  d.add(2, 1);
  d.seal();
  EXPECT_TRUE(d.contains(7, 9));
  EXPECT_TRUE(d.contains(2, 1));
  EXPECT_FALSE(d.contains(7, 4));
  EXPECT_FALSE(d.contains(2, 9));  // run 9 is done, with another key
  EXPECT_TRUE(d.has(3));
  EXPECT_FALSE(d.has(2));
  EXPECT_FALSE(d.has(10));
  ASSERT_EQ(d.size(), 3U);
  EXPECT_EQ(d.rows().front().index, 1U);
  EXPECT_EQ(d.rows().back().index, 9U);
}

TEST(DoneRuns, ParsesKeysAndIndices) {
  EXPECT_EQ(parse_run_key("00000000000000ff"), 255U);
  EXPECT_FALSE(parse_run_key("ff"));
  EXPECT_FALSE(parse_run_key("00000000000000fg"));
  EXPECT_EQ(parse_run_index("42"), 42U);
  EXPECT_FALSE(parse_run_index(""));
  EXPECT_FALSE(parse_run_index("4x"));
  EXPECT_FALSE(parse_run_index("-1"));
  EXPECT_FALSE(parse_run_index("+1"));
  EXPECT_FALSE(parse_run_index(" 1"));
  EXPECT_FALSE(parse_run_index("18446744073709551616"));  // 2^64
  EXPECT_EQ(parse_run_index("18446744073709551615"), 18446744073709551615ULL);
}

}  // namespace
}  // namespace fsweep
