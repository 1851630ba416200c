// DoneRuns: the runs a resumed sweep skips; RunPlacement: where they go in an extended sweep.
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

TEST(RunPlacement, PlacesRowsByKeyInRunOrderAndNamesThoseWithoutAPlace) {
  // Done rows (key, index): two of key 5 (a configuration two strategy entries reach), one of
  // key 8, one of key 9 that the new plan does not have.
  DoneRuns d;
  d.add(5, 4);
  d.add(8, 0);
  d.add(5, 2);
  d.add(9, 3);
  d.seal();
  RunPlacement p(d);
  // The new plan's runs 0..7 have keys 1, 5, 8, 1, 5, 5, 2, 8.
  const std::uint64_t keys[] = {1, 5, 8, 1, 5, 5, 2, 8};
  for (std::uint64_t i = 0; i < 8; ++i) p.offer(i, keys[i]);
  EXPECT_FALSE(p.complete());
  p.seal();
  EXPECT_EQ(p.placed(), 3U);
  EXPECT_EQ(p.new_index(5, 2), 1U);  // the earlier row of key 5 takes the earlier run
  EXPECT_EQ(p.new_index(5, 4), 4U);
  EXPECT_EQ(p.new_index(8, 0), 2U);
  EXPECT_FALSE(p.new_index(9, 3));
  EXPECT_FALSE(p.new_index(5, 3));  // no done row, and no row of key 5 placed at run 3
  // A row already renumbered (a kill between the rewrites of the two files) is found where it went.
  EXPECT_EQ(p.new_index(8, 2), 2U);
  EXPECT_EQ(p.new_index(5, 1), 1U);
  const std::vector<DoneRuns::Row> unplaced = p.unplaced();
  ASSERT_EQ(unplaced.size(), 1U);
  EXPECT_EQ(unplaced[0].index, 3U);
  EXPECT_EQ(unplaced[0].key, 9U);
}

TEST(RunPlacement, IsCompleteOnceEveryRowHasItsPlace) {
  DoneRuns d;
  d.add(3, 0);
  d.seal();
  RunPlacement p(d);
  EXPECT_FALSE(p.complete());
  p.offer(6, 3);
  EXPECT_TRUE(p.complete());
  p.offer(7, 3);  // a later run of the same key: nothing left to place
  p.seal();
  EXPECT_EQ(p.new_index(3, 0), 6U);
  EXPECT_TRUE(p.unplaced().empty());
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
