/// The plan benchmark library (src/evaluation/plan_bench.hpp) on hand-worked cases.

#include <gtest/gtest.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "evaluation/plan_bench.hpp"
#include "planners/planner_test_utils.hpp"
#include "planners/registry.hpp"

namespace fsweep {
namespace {

using testing::known_from_ascii;

TEST(PlanBench, ScenarioQueriesSkipUnreachableOnes) {
  std::vector<ScenarioQuery> scen(3);
  scen[0].start = Cell{0, 0};
  scen[0].goal = Cell{2, 0};
  scen[0].optimal_length = 2.0;
  scen[1].optimal_length = 0.0;  // GPPC: unreachable
  scen[2].start = Cell{1, 1};
  scen[2].goal = Cell{0, 0};
  scen[2].optimal_length = kSqrt2;
  const std::vector<BenchQuery> q = bench_queries_from_scenario(scen);
  ASSERT_EQ(q.size(), 2U);
  EXPECT_EQ(q[0].goal, (Cell{2, 0}));
  EXPECT_DOUBLE_EQ(q[1].optimal_cells, kSqrt2);
}

TEST(PlanBench, RandomPairsCarryOptimalOctileLengths) {
  // A 3-cell corridor has exactly 3 unordered pairs: lengths 1, 1 and 2 cells (resolution 0.5 m
  // does not change lengths in cells).
  const auto m = known_from_ascii({"..."}, 0.5);
  PairDrawOptions draw;
  draw.count = 3;
  draw.seed = 4;
  const std::vector<BenchQuery> q = bench_queries_from_pairs(m.known, draw);
  ASSERT_EQ(q.size(), 3U);
  double total = 0.0;
  for (const BenchQuery& b : q) {
    EXPECT_DOUBLE_EQ(b.optimal_cells, std::abs(b.goal.x - b.start.x));
    total += b.optimal_cells;
  }
  EXPECT_DOUBLE_EQ(total, 4.0);
}

TEST(PlanBench, OptimalPlannerHasRatioOneAndFailuresAreCounted) {
  // Around a wall; the optimum is astar's own length (resolution 1 m), so astar's ratio is 1.
  const auto m = known_from_ascii({"S.#..", "..#..", "....G"});
  PlanRequest r;
  r.start = m.start;
  r.goal = m.goal;
  const double optimal = make_planner("astar", nullptr)->plan(m.known, r).length_m;
  // The second query goes to a blocked cell: GoalInvalid for every planner.
  const std::vector<BenchQuery> queries{{m.start, m.goal, optimal}, {m.start, Cell{2, 0}, 3.0}};
  std::vector<std::unique_ptr<Planner>> planners;
  planners.push_back(make_planner("astar", nullptr));
  planners.push_back(make_planner("ompl:RRTConnect", {{"time_limit_s", 0.2}}));
  const auto plans = run_plan_bench(m.known, queries, planners, BenchSettings{});
  ASSERT_EQ(plans.size(), 2U);
  EXPECT_EQ(plans[0][0].status, PlanStatus::Success);
  EXPECT_DOUBLE_EQ(plans[0][0].length_ratio, 1.0);
  ASSERT_EQ(plans[1][0].status, PlanStatus::Success);
  EXPECT_GE(plans[1][0].length_ratio, 1.0 - 1e-12);
  EXPECT_EQ(plans[0][1].status, PlanStatus::GoalInvalid);
  EXPECT_EQ(plans[1][1].length_ratio, 0.0);
  const BenchSummary s = summarize_plan_bench(plans[0]);
  EXPECT_EQ(s.queries, 2);
  EXPECT_EQ(s.solved, 1);
  EXPECT_DOUBLE_EQ(s.success_rate, 0.5);
}

TEST(PlanBench, SummaryStatisticsByHand) {
  // Solved ratios {1.0, 1.5}: mean = median = 1.25; times {1, 3, 2} ms over all three queries:
  // median 2 ms; one timeout.
  std::vector<BenchPlan> plans(3);
  plans[0] = BenchPlan{PlanStatus::Success, 1.0, 10.0, 2, 0.001, 10.0, {}};
  plans[1] = BenchPlan{PlanStatus::Success, 1.5, 20.0, 4, 0.003, 15.0, {}};
  plans[2] = BenchPlan{PlanStatus::Timeout, 0.0, 0.0, 0, 0.002, 0.0, {}};
  const BenchSummary s = summarize_plan_bench(plans);
  EXPECT_EQ(s.queries, 3);
  EXPECT_EQ(s.solved, 2);
  EXPECT_EQ(s.timeouts, 1);
  EXPECT_NEAR(s.success_rate, 2.0 / 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.length_ratio.mean, 1.25);
  EXPECT_DOUBLE_EQ(s.length_ratio.median, 1.25);
  EXPECT_DOUBLE_EQ(s.energy.mean, 15.0);
  EXPECT_DOUBLE_EQ(s.turns.mean, 3.0);
  EXPECT_DOUBLE_EQ(s.time_ms.median, 2.0);
}

}  // namespace
}  // namespace fsweep
