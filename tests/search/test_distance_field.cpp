#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "planners/grid_planner.hpp"
#include "planners/planner_test_utils.hpp"
#include "search/distance_field.hpp"

namespace fsweep {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

DistanceQuery bounded_query(double max_distance_m) {
  DistanceQuery q;
  q.max_distance_m = max_distance_m;
  return q;
}

DistanceQuery corner_cutting(bool allow) {
  DistanceQuery q;
  q.allow_corner_cutting = allow;
  return q;
}

TEST(DistanceField, MatchesPlannerLengths) {
  GridPlanner astar(GridSearchKind::AStar);
  DistanceField field;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const KnownMap known = testing::random_known_map(35, 28, 0.3, seed, 0.25);
    Rng rng = make_rng(seed, "queries");
    for (int q = 0; q < 6; ++q) {
      const bool cut = q % 3 == 2;
      const Cell source = testing::random_free_cell(known, rng);
      field.compute(known, source, corner_cutting(cut));
      EXPECT_EQ(field.source(), source);
      for (int t = 0; t < 15; ++t) {
        const Cell target = testing::random_free_cell(known, rng);
        PlanRequest req;
        req.start = source;
        req.goal = target;
        req.allow_corner_cutting = cut;
        const PlanResult plan = astar.plan(known, req);
        const int i = known.index(target);
        if (plan.status == PlanStatus::Success) {
          EXPECT_EQ(field.distance_m(i), plan.length_m);  // exact costs: bit for bit
        } else {
          EXPECT_EQ(plan.status, PlanStatus::NoPath);
          EXPECT_FALSE(field.reached(i));
        }
      }
    }
  }
}

TEST(DistanceField, BoundRespected) {
  const KnownMap known = testing::random_known_map(60, 60, 0.2, 7, 0.5);
  const Cell source{30, 30};
  ASSERT_TRUE(known.is_free(source));
  DistanceField full;
  full.compute(known, source, {});
  DistanceField bounded;
  bounded.compute(known, source, bounded_query(6.0));
  int inside = 0;
  for (int i = 0; i < known.size(); ++i) {
    const double d = full.distance_m(i);
    if (d <= 6.0) {
      ++inside;
      EXPECT_DOUBLE_EQ(bounded.distance_m(i), d);
    } else {
      EXPECT_EQ(bounded.distance_m(i), kInf) << "cell " << i << " at " << d << " m";
    }
  }
  EXPECT_GT(inside, 50);
  EXPECT_EQ(bounded.expansions(), inside);
  EXPECT_LT(bounded.expansions(), full.expansions());
}

TEST(DistanceField, BoundIsInclusive) {
  // A cell exactly on the bound (in metres, up to rounding) is reached.
  const auto m = testing::known_from_ascii({"S..........."}, 0.1);
  DistanceField field;
  field.compute(m.known, m.start, bounded_query(1.0));
  EXPECT_TRUE(field.reached(10));
  EXPECT_FALSE(field.reached(11));
  // 0.3 / 0.1 is 2.9999999999999996 in doubles; the cell 3 steps away is still on the bound.
  field.compute(m.known, m.start, bounded_query(0.3));
  EXPECT_TRUE(field.reached(3));
  EXPECT_FALSE(field.reached(4));
}

TEST(DistanceField, EarlyStopReturnsExactNearestTarget) {
  const KnownMap known = testing::random_known_map(50, 50, 0.2, 11);
  const Cell source{25, 25};
  ASSERT_TRUE(known.is_free(source));
  DistanceField full;
  full.compute(known, source, {});
  Rng rng = make_rng(11, "targets");
  DistanceField early;  // reused: earlier rounds' targets must not stop later rounds
  for (int round = 0; round < 20; ++round) {
    std::vector<int> targets;
    targets.reserve(5);
    for (int k = 0; k < 5; ++k) targets.push_back(known.index(testing::random_free_cell(known, rng)));
    double nearest = kInf;
    for (const int t : targets) nearest = std::min(nearest, full.distance_m(t));

    early.compute(known, source, DistanceQuery{.stop_at_first_of = targets});
    for (const int t : targets) {
      if (full.distance_m(t) == nearest && nearest < kInf) {
        EXPECT_DOUBLE_EQ(early.distance_m(t), nearest);  // the nearest target(s): exact
      } else if (early.reached(t)) {
        EXPECT_DOUBLE_EQ(early.distance_m(t), full.distance_m(t));  // settled ones are exact too
      }
    }
    // Every cell strictly closer than the nearest target is settled; nothing farther is.
    for (int i = 0; i < known.size(); ++i) {
      if (full.distance_m(i) < nearest) {
        EXPECT_TRUE(early.reached(i));
      }
      if (early.reached(i)) {
        EXPECT_LE(early.distance_m(i), nearest + 1e-9);
      }
    }
    if (nearest < kInf) {
      EXPECT_LT(early.expansions(), full.expansions());
    }
  }
}

TEST(DistanceField, EarlyStopSettlesAllTiedTargets) {
  // Two targets at 3 + sqrt(2) cells, reached by paths whose steps come in different orders.
  const auto m = testing::known_from_ascii({".........", ".........", "....S....", ".........", "........."});
  const std::vector<int> targets{m.known.index(Cell{0, 1}), m.known.index(Cell{8, 3}),
                                 m.known.index(Cell{8, 0})};
  DistanceField field;
  field.compute(m.known, m.start, DistanceQuery{.stop_at_first_of = targets});
  EXPECT_DOUBLE_EQ(field.distance_m(targets[0]), 3.0 + kSqrt2);
  EXPECT_DOUBLE_EQ(field.distance_m(targets[1]), 3.0 + kSqrt2);
  EXPECT_FALSE(field.reached(targets[2]));  // 2 + 2 sqrt(2) is farther
}

TEST(DistanceField, SourceAsTargetStopsImmediately) {
  const auto m = testing::known_from_ascii({"S....", "....."});
  const std::vector<int> targets{m.known.index(m.start), 4};
  DistanceField field;
  field.compute(m.known, m.start, DistanceQuery{.stop_at_first_of = targets});
  EXPECT_EQ(field.distance_m(m.known.index(m.start)), 0.0);
  EXPECT_EQ(field.expansions(), 1);
  EXPECT_FALSE(field.reached(4));
}

TEST(DistanceField, NonFreeSourceGivesEmptyField) {
  const auto m = testing::known_from_ascii({"S.#", "..?"});
  DistanceField field;
  field.compute(m.known, m.start, {});
  EXPECT_TRUE(field.reached(1));
  for (const Cell bad : {Cell{2, 0}, Cell{2, 1}, Cell{-1, 0}, Cell{3, 1}}) {
    field.compute(m.known, bad, {});  // also forgets the previous field
    for (int i = 0; i < m.known.size(); ++i) EXPECT_FALSE(field.reached(i));
    EXPECT_EQ(field.expansions(), 0);
  }
}

TEST(DistanceField, CornerCuttingFlagHonoured) {
  const auto m = testing::known_from_ascii({"S#", "#."});
  DistanceField field;
  field.compute(m.known, m.start, {});
  EXPECT_FALSE(field.reached(3));
  field.compute(m.known, m.start, corner_cutting(true));
  EXPECT_DOUBLE_EQ(field.distance_m(3), kSqrt2);
}

/// Records what a watched search reports and stops it at a given radius.
struct RecordingWatcher final : SettleWatcher {
  double stop_beyond_m = kInf;
  std::vector<std::pair<std::size_t, double>> reported;
  std::vector<double> asked;
  void settled(std::size_t position, double distance_m) override {
    reported.emplace_back(position, distance_m);
  }
  double go_on_until(double radius_m) override {
    asked.push_back(radius_m);
    return radius_m > stop_beyond_m ? -kInf : stop_beyond_m;
  }
};

TEST(DistanceField, WatcherSeesEveryTargetInOrderWithTheFieldsDistances) {
  DistanceField full;
  DistanceField watched;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const KnownMap known = testing::random_known_map(40, 30, 0.25, seed, 0.5);
    Rng rng = make_rng(seed, "watched");
    const Cell source = testing::random_free_cell(known, rng);
    std::vector<int> targets;
    for (int t = 0; t < 12; ++t) targets.push_back(known.index(testing::random_free_cell(known, rng)));
    targets.push_back(targets.front());  // a cell listed twice is reported at both positions
    targets.push_back(-5);               // off the grid: ignored
    const double bound = seed % 2 == 0 ? 9.0 : kInf;
    full.compute(known, source, bounded_query(bound));
    RecordingWatcher w;
    DistanceQuery q = bounded_query(bound);
    q.stop_when_all_settled = targets;
    q.watcher = &w;
    watched.compute(known, source, q);
    std::vector<std::size_t> expected;
    for (std::size_t p = 0; p + 1 < targets.size(); ++p) {
      if (full.reached(targets[p])) expected.push_back(p);
    }
    ASSERT_EQ(w.reported.size(), expected.size()) << "seed " << seed;
    double last = 0.0;
    for (const auto& [p, d] : w.reported) {
      EXPECT_EQ(d, full.distance_m(targets[p])) << "seed " << seed << " position " << p;  // bit for bit
      EXPECT_GE(d, last);
      last = d;
    }
    // The watcher is asked before the first cell and again after every settled target, each
    // time with a radius no target reported later undercuts.
    ASSERT_FALSE(w.asked.empty());
    EXPECT_EQ(w.asked.front(), 0.0);
    EXPECT_TRUE(std::is_sorted(w.asked.begin(), w.asked.end()));
  }
}

TEST(DistanceField, WatcherStopsTheSearch) {
  const KnownMap known = testing::random_known_map(60, 60, 0.0, 3, 1.0);
  const std::vector<int> targets{known.index(Cell{2, 0}), known.index(Cell{30, 0}),
                                 known.index(Cell{59, 59})};
  DistanceField field;
  RecordingWatcher w;
  w.stop_beyond_m = 10.0;
  DistanceQuery q;
  q.stop_when_all_settled = targets;
  q.watcher = &w;
  field.compute(known, Cell{0, 0}, q);
  ASSERT_EQ(w.reported.size(), 1U);
  EXPECT_EQ(w.reported[0].first, 0U);
  EXPECT_DOUBLE_EQ(w.reported[0].second, 2.0);
  EXPECT_GT(w.asked.back(), 10.0);  // asked once beyond its radius, and stopped there
  EXPECT_TRUE(field.reached(known.index(Cell{10, 0})));
  EXPECT_FALSE(field.reached(known.index(Cell{11, 0})));
  EXPECT_LT(field.expansions(), 200);
}

TEST(OctileCost, ValuesAreExactLengths) {
  // The value of the octile cost is octile_distance() bit for bit, and on an open grid every
  // field distance is exactly the octile length (summed doubles would drift in the last bits).
  const KnownMap known = testing::random_known_map(300, 200, 0.0, 1, 1.0);
  DistanceField field;
  field.compute(known, Cell{150, 100}, DistanceQuery{});
  for (int i = 0; i < known.size(); i += 7) {
    const Cell c = known.cell(i);
    EXPECT_EQ(octile_cost(Cell{150, 100}, c).value(), octile_distance(Cell{150, 100}, c));
    ASSERT_EQ(field.distance_m(i), octile_distance(Cell{150, 100}, c)) << c.x << "," << c.y;
  }
  // Equal lengths compare equal, different ones in the order of their real values.
  EXPECT_EQ((OctileCost{3, 2} + OctileCost{1, 1}).value(), (OctileCost{4, 3}).value());
  EXPECT_GT((OctileCost{0, 29}).value(), (OctileCost{41, 0}).value());  // 29 sqrt(2) = 41.01...
  EXPECT_LT((OctileCost{0, 70}).value(), (OctileCost{99, 0}).value());  // 70 sqrt(2) = 98.99...
}

TEST(DistanceField, OneLengthByAStarEqualsTheFieldsBitForBit) {
  DistanceField field;
  DistanceField point;
  int reached = 0;
  int unreached = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const KnownMap known = testing::random_known_map(40, 30, 0.3, seed, 0.25);
    Rng rng = make_rng(seed, "point");
    const Cell source = testing::random_free_cell(known, rng);
    DistanceQuery q = bounded_query(seed % 2 == 0 ? 4.0 : kInf);
    q.allow_corner_cutting = seed % 3 == 0;
    field.compute(known, source, q);
    for (int t = 0; t < 40; ++t) {
      const Cell goal = testing::random_free_cell(known, rng);
      const std::optional<double> d = point.compute_to(known, source, goal, q);
      ASSERT_TRUE(d.has_value());
      // The same bound rule too: beyond max_distance_m both read +infinity.
      const double expected = field.distance_m(known.index(goal));
      EXPECT_EQ(*d, expected) << "seed " << seed << " goal " << goal.x << "," << goal.y;
      ++(std::isinf(*d) ? unreached : reached);
      // Every cell the A* settled reads its exact length, as the field does.
      for (int i = 0; i < known.size(); ++i) {
        if (point.reached(i)) {
          ASSERT_EQ(point.distance_m(i), field.distance_m(i)) << "seed " << seed;
        }
      }
    }
  }
  EXPECT_GT(reached, 50);
  EXPECT_GT(unreached, 50);  // the 4 m bound and walled-in cells
}

TEST(DistanceField, OneLengthByAStarWithBudgetAndBlockedGoals) {
  const KnownMap known = testing::random_known_map(60, 60, 0.0, 1, 1.0);
  DistanceField point;
  // Open space: A* with exact ties settles about one cell per cell of length.
  EXPECT_EQ(point.compute_to(known, Cell{0, 0}, Cell{50, 20}, DistanceQuery{}),
            octile_distance(Cell{0, 0}, Cell{50, 20}));
  EXPECT_LE(point.expansions(), 51);
  // A budget below that: no answer, rather than a wrong one.
  DistanceQuery tight;
  tight.stop = StopCondition(SearchBudget{kInf, 10}, StopCondition::Clock::now());
  EXPECT_FALSE(point.compute_to(known, Cell{0, 0}, Cell{50, 20}, tight).has_value());
  EXPECT_TRUE(point.stopped());
  // An occupied or unknown goal is unreachable at once, and the field reads empty.
  const KnownMap walls = testing::known_from_ascii({"..#", "..?"}).known;
  EXPECT_EQ(point.compute_to(walls, Cell{0, 0}, Cell{2, 0}, DistanceQuery{}), kInf);
  EXPECT_EQ(point.expansions(), 0);
  EXPECT_EQ(point.compute_to(walls, Cell{0, 0}, Cell{2, 1}, DistanceQuery{}), kInf);
  EXPECT_EQ(point.expansions(), 0);
  for (int i = 0; i < walls.size(); ++i) EXPECT_FALSE(point.reached(i));
}

TEST(DistanceField, TargetsOfOneQueryDoNotStopTheNext) {
  // The stop targets are marked for one compute() only: a later query without targets, or with
  // other ones, on the same field runs as on a fresh one.
  const KnownMap known = testing::random_known_map(50, 40, 0.2, 3, 1.0);
  Rng rng = make_rng(3, "targets");
  DistanceField reused;
  for (int round = 0; round < 30; ++round) {
    const Cell source = testing::random_free_cell(known, rng);
    std::vector<int> targets;
    for (int k = 0; k < 1 + round % 4; ++k)
      targets.push_back(known.index(testing::random_free_cell(known, rng)));
    DistanceQuery q;
    if (round % 2 == 0) {
      q.stop_at_first_of = targets;
    } else {
      q.stop_when_all_settled = targets;
    }
    reused.compute(known, source, q);
    DistanceField fresh;
    fresh.compute(known, source, q);
    for (int i = 0; i < known.size(); ++i)
      ASSERT_EQ(reused.distance_m(i), fresh.distance_m(i)) << "round " << round;
    EXPECT_EQ(reused.expansions(), fresh.expansions());
    if (round % 5 == 4) (void)reused.compute_to(known, source, known.cell(targets.front()), DistanceQuery{});
  }
}

}  // namespace
}  // namespace fsweep
