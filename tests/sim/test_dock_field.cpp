// DockField: the dock's distance field, brought up to date lazily and shared copy-on-write.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "sim/dock_field.hpp"
#include "world/known_map.hpp"

namespace fsweep {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Reveals cells [from, to) of row 0 of `known` as free; returns their indices.
std::vector<int> reveal_row(KnownMap& known, int from, int to) {
  std::vector<int> revealed;
  for (int x = from; x < to; ++x) {
    if (known.reveal(known.index(Cell{x, 0}), false)) revealed.push_back(known.index(Cell{x, 0}));
  }
  return revealed;
}

TEST(DockField, BuiltWhenFirstAskedThenUpdatedOnlyWhenAsked) {
  KnownMap known(6, 1, 1.0);
  DockField field;
  field.take_in(known, reveal_row(known, 3, 4), Cell{0, 0}, false);  // the dock is still unknown
  EXPECT_FALSE(field.ready());
  field.take_in(known, reveal_row(known, 0, 2), Cell{0, 0}, false);
  ASSERT_TRUE(field.ready());
  EXPECT_FALSE(field.built());  // no decision asked yet: no field
  EXPECT_FALSE(field.current());
  EXPECT_EQ(field.bring_up_to_date(known), 2);  // built on the map as it is now
  ASSERT_TRUE(field.built());
  EXPECT_TRUE(field.current());
  EXPECT_DOUBLE_EQ(field.distance_m(1), 1.0);
  EXPECT_EQ(field.distance_m(3), kInf);  // cell 2 is still unknown
  field.take_in(known, reveal_row(known, 2, 3), Cell{0, 0}, false);
  EXPECT_FALSE(field.current());
  EXPECT_EQ(field.distance_m(3), kInf);  // not brought up to date yet
  EXPECT_GT(field.bring_up_to_date(known), 0);
  EXPECT_DOUBLE_EQ(field.distance_m(3), 3.0);
  EXPECT_EQ(field.bring_up_to_date(known), 0);  // nothing pending
}

TEST(DockField, ACopyUpdatedOnItsOwnMapLeavesTheOriginalsField) {
  KnownMap known(6, 1, 1.0);
  DockField original;
  original.take_in(known, reveal_row(known, 0, 3), Cell{0, 0}, false);
  ASSERT_TRUE(original.ready());
  (void)original.bring_up_to_date(known);

  KnownMap forked_known = known;
  DockField fork = original;  // shares the field until one of them updates it
  fork.take_in(forked_known, reveal_row(forked_known, 3, 6), Cell{0, 0}, false);
  fork.bring_up_to_date(forked_known);
  EXPECT_DOUBLE_EQ(fork.distance_m(5), 5.0);
  EXPECT_EQ(original.distance_m(5), kInf);
  EXPECT_EQ(original.distance_m(3), kInf);
  EXPECT_DOUBLE_EQ(original.distance_m(2), 2.0);

  // And the original, updated on its own map, leaves the fork's.
  original.take_in(known, reveal_row(known, 3, 4), Cell{0, 0}, false);
  original.bring_up_to_date(known);
  EXPECT_DOUBLE_EQ(original.distance_m(3), 3.0);
  EXPECT_EQ(original.distance_m(4), kInf);
  EXPECT_DOUBLE_EQ(fork.distance_m(4), 4.0);
}

TEST(DockField, ManyRevealedCellsBuildTheFieldAgainWithTheSameLengths) {
  // A row of 5000 cells: revealing more than rebuild_after() cells since the last update drops
  // the list of revealed cells, and the next update is a full search (it settles every
  // reachable cell) with the lengths an update gives.
  constexpr int kWidth = 5000;
  ASSERT_EQ(DockField::rebuild_after(kWidth), 1024U);
  KnownMap known(kWidth, 1, 1.0);
  DockField field;
  field.take_in(known, reveal_row(known, 0, 10), Cell{0, 0}, false);
  EXPECT_EQ(field.bring_up_to_date(known), 10);
  field.take_in(known, reveal_row(known, 10, 20), Cell{0, 0}, false);
  EXPECT_EQ(field.bring_up_to_date(known), 10);  // an update: the 10 new cells
  for (int x = 20; x < 1000; x += 10) field.take_in(known, reveal_row(known, x, x + 10), Cell{0, 0}, false);
  EXPECT_EQ(field.bring_up_to_date(known), 980);  // 980 cells: still an update
  for (int x = 1000; x < 3000; x += 10) field.take_in(known, reveal_row(known, x, x + 10), Cell{0, 0}, false);
  EXPECT_FALSE(field.current());
  EXPECT_EQ(field.bring_up_to_date(known), 3000);  // 2000 cells: built again
  for (int x = 0; x < kWidth; ++x) EXPECT_EQ(field.distance_m(x), x < 3000 ? x : kInf) << x;
  DockField shared = field;  // built again while a copy shares the field: the copy keeps its own
  for (int x = 3000; x < kWidth; x += 10)
    field.take_in(known, reveal_row(known, x, x + 10), Cell{0, 0}, false);
  EXPECT_EQ(field.bring_up_to_date(known), kWidth);
  EXPECT_EQ(field.distance_m(kWidth - 1), kWidth - 1);
  EXPECT_EQ(shared.distance_m(kWidth - 1), kInf);
}

}  // namespace
}  // namespace fsweep
