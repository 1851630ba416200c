/// The planner comparison of `fsweep plan-compare` (Mei et al. 2006 section V-B): drawing the
/// query pairs (distinct, reachable, seeded) and the statistics, checked on hand-computed cases.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <set>
#include <utility>

#include "core/config_error.hpp"
#include "evaluation/plan_compare.hpp"
#include "planners/grid_planner.hpp"
#include "planners/lattice_planner.hpp"
#include "planners/planner_test_utils.hpp"
#include "planners/shortest_fewest_turns.hpp"
#include "world/energy_model.hpp"

namespace fsweep {
namespace {

using testing::known_from_ascii;

// Two regions split by a wall column: 4 x 3 = 12 free cells on the left, 3 x 3 = 9 on the right.
testing::AsciiKnownMap two_regions() {
  return known_from_ascii({
      "....#...",
      "....#...",
      "....#...",
  });
}

TEST(DrawComparePairs, DistinctReachableAndDeterministic) {
  const auto m = two_regions();
  PairDrawOptions o;
  o.count = 60;
  o.seed = 7;
  const auto pairs = draw_compare_pairs(m.known, o);
  ASSERT_EQ(pairs.size(), 60U);
  std::set<std::pair<int, int>> seen;
  for (const ComparePair& p : pairs) {
    EXPECT_NE(p.source, p.target);
    EXPECT_TRUE(m.known.is_free(p.source));
    EXPECT_TRUE(m.known.is_free(p.target));
    EXPECT_EQ(p.source.x < 4, p.target.x < 4) << "pair crosses the wall";
    EXPECT_GE(p.start_heading, 0);
    EXPECT_LE(p.start_heading, 7);
    const int a = m.known.index(p.source);
    const int b = m.known.index(p.target);
    EXPECT_TRUE(seen.insert({std::min(a, b), std::max(a, b)}).second) << "repeated pair";
  }
  const auto again = draw_compare_pairs(m.known, o);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    EXPECT_EQ(again[k].source, pairs[k].source);
    EXPECT_EQ(again[k].target, pairs[k].target);
    EXPECT_EQ(again[k].start_heading, pairs[k].start_heading);
  }
  o.seed = 8;
  const auto other = draw_compare_pairs(m.known, o);
  int same = 0;
  for (std::size_t k = 0; k < pairs.size(); ++k) same += other[k].source == pairs[k].source ? 1 : 0;
  EXPECT_LT(same, 30);
}

TEST(DrawComparePairs, FixedHeadingKeepsThePairs) {
  const auto m = two_regions();
  PairDrawOptions o;
  o.count = 20;
  const auto random_heading = draw_compare_pairs(m.known, o);
  o.start_heading = 3;
  const auto fixed_heading = draw_compare_pairs(m.known, o);
  std::set<int> headings;
  for (std::size_t k = 0; k < random_heading.size(); ++k) {
    EXPECT_EQ(fixed_heading[k].source, random_heading[k].source);
    EXPECT_EQ(fixed_heading[k].target, random_heading[k].target);
    EXPECT_EQ(fixed_heading[k].start_heading, 3);
    headings.insert(random_heading[k].start_heading);
  }
  EXPECT_GT(headings.size(), 3U);
}

TEST(DrawComparePairs, AllPairsOfATinyMapAndNoMore) {
  // 12 * 11 / 2 + 9 * 8 / 2 = 66 + 36 = 102 distinct reachable unordered pairs.
  const auto m = two_regions();
  PairDrawOptions o;
  o.count = 102;
  EXPECT_EQ(draw_compare_pairs(m.known, o).size(), 102U);
  o.count = 103;
  EXPECT_THROW((void)draw_compare_pairs(m.known, o), ConfigError);
  o.count = 0;
  EXPECT_THROW((void)draw_compare_pairs(m.known, o), ConfigError);
  o.count = 1;
  o.start_heading = 8;
  EXPECT_THROW((void)draw_compare_pairs(m.known, o), ConfigError);
  const auto lonely = known_from_ascii({".#.", "###"});  // two free cells, not connected
  o.start_heading.reset();
  EXPECT_THROW((void)draw_compare_pairs(lonely.known, o), ConfigError);
}

TEST(SummarizeSample, Type7QuantilesByHand) {
  // h = 4 q: q05 -> 0.2 -> 1.2, q25 -> 1 -> 2, median 3, q75 4, q95 -> 3.8 -> 4.8.
  const SampleSummary s = summarize_sample({5, 1, 4, 2, 3});
  EXPECT_DOUBLE_EQ(s.mean, 3.0);
  EXPECT_DOUBLE_EQ(s.q05, 1.2);
  EXPECT_DOUBLE_EQ(s.q25, 2.0);
  EXPECT_DOUBLE_EQ(s.median, 3.0);
  EXPECT_DOUBLE_EQ(s.q75, 4.0);
  EXPECT_DOUBLE_EQ(s.q95, 4.8);
  EXPECT_TRUE(std::isnan(summarize_sample({}).mean));
}

PairPlan ok(double length, double energy, int stops = 0, int turns = 0) {
  return PairPlan{PlanStatus::Success, length, energy, stops, turns, 10, 0.002};
}

TEST(SummarizeComparison, SavingsByHand) {
  // Four pairs; the candidate fails the fourth, which is left out of the contrast.
  //   pair 1: E 10 -> 9   (saving 10%),  L 10 -> 11 (increase 10%)  cheaper
  //   pair 2: E 20 -> 20  (saving 0%),   L 10 -> 10 (0%)            equal
  //   pair 3: E 10 -> 12  (saving -20%), L 20 -> 20 (0%)            dearer
  // mean saving -10/3; totals: E 40 -> 41: 100 (40 - 41) / 40 = -2.5%; L 40 -> 41: +2.5%.
  std::vector<std::vector<PairPlan>> plans(2);
  plans[0] = {ok(10, 10, 2, 2), ok(10, 20, 4, 4), ok(20, 10, 0, 0), ok(5, 5, 1, 1)};
  plans[1] = {ok(11, 9, 1, 1), ok(10, 20, 4, 4), ok(20, 12, 3, 3), PairPlan{}};
  const CompareSummary s = summarize_comparison(plans);
  ASSERT_EQ(s.totals.size(), 2U);
  EXPECT_EQ(s.totals[0].solved, 4);
  EXPECT_EQ(s.totals[1].solved, 3);
  EXPECT_DOUBLE_EQ(s.totals[0].mean_stops, 7.0 / 4.0);
  EXPECT_DOUBLE_EQ(s.totals[1].mean_turns, 8.0 / 3.0);
  EXPECT_DOUBLE_EQ(s.totals[1].mean_time_s, 0.002);
  ASSERT_EQ(s.contrasts.size(), 1U);
  const PlannerContrast& c = s.contrasts[0];
  EXPECT_EQ(c.baseline, 0);
  EXPECT_EQ(c.candidate, 1);
  EXPECT_EQ(c.pairs_used, 3);
  EXPECT_NEAR(c.energy_saving_pct.mean, -10.0 / 3.0, 1e-12);
  EXPECT_NEAR(c.energy_saving_pct.median, 0.0, 1e-12);
  EXPECT_NEAR(c.energy_saving_pct.q05, -20.0 + 0.1 * 20.0, 1e-12);  // h = 0.1 between -20 and 0
  EXPECT_NEAR(c.length_increase_pct.mean, 10.0 / 3.0, 1e-12);
  EXPECT_NEAR(c.total_energy_saving_pct, -2.5, 1e-12);
  EXPECT_NEAR(c.total_length_increase_pct, 2.5, 1e-12);
  EXPECT_DOUBLE_EQ(c.share_cheaper, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(c.share_equal, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(c.share_dearer, 1.0 / 3.0);
}

TEST(SummarizeComparison, EveryPlannerPairInOrder) {
  std::vector<std::vector<PairPlan>> plans(3, std::vector<PairPlan>{ok(1, 1)});
  const CompareSummary s = summarize_comparison(plans);
  ASSERT_EQ(s.contrasts.size(), 3U);
  EXPECT_EQ(std::make_pair(s.contrasts[0].baseline, s.contrasts[0].candidate), std::make_pair(0, 1));
  EXPECT_EQ(std::make_pair(s.contrasts[1].baseline, s.contrasts[1].candidate), std::make_pair(0, 2));
  EXPECT_EQ(std::make_pair(s.contrasts[2].baseline, s.contrasts[2].candidate), std::make_pair(1, 2));
  EXPECT_DOUBLE_EQ(s.contrasts[2].share_equal, 1.0);
}

TEST(PlanComparePairs, SameRequestsForEveryPlanner) {
  const KnownMap known = testing::random_known_map(30, 30, 0.2, 5);
  PairDrawOptions o;
  o.count = 80;
  const auto pairs = draw_compare_pairs(known, o);
  std::vector<std::unique_ptr<Planner>> planners;
  planners.push_back(std::make_unique<GridPlanner>(GridSearchKind::Dijkstra));
  planners.push_back(std::make_unique<ShortestFewestTurnsPlanner>());
  planners.push_back(std::make_unique<LatticePlanner>(LatticeSearchKind::AStar));
  const auto plans = plan_compare_pairs(known, pairs, planners, energy_preset("mei2006"), false);
  ASSERT_EQ(plans.size(), 3U);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    ASSERT_EQ(plans[0][k].status, PlanStatus::Success);  // pairs are reachable
    EXPECT_NEAR(plans[1][k].length_m, plans[0][k].length_m, 1e-9);
    EXPECT_LE(plans[1][k].energy, plans[0][k].energy + 1e-9);
    EXPECT_LE(plans[2][k].energy, plans[1][k].energy + 1e-9);
  }
  const CompareSummary s = summarize_comparison(plans);
  EXPECT_DOUBLE_EQ(s.contrasts[0].share_dearer, 0.0);  // sft never dearer than dijkstra
  EXPECT_NEAR(s.contrasts[0].length_increase_pct.q95, 0.0, 1e-9);
  EXPECT_GT(s.contrasts[1].energy_saving_pct.mean, 0.0);  // lattice saves against dijkstra
}

}  // namespace
}  // namespace fsweep
