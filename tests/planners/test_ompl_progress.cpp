/// OMPL planners' progress properties (PlanRequest::progress_interval_s, PlanResult::progress):
/// which planners report what, when samples are taken, and that sampling leaves results alone.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "planner_test_utils.hpp"
#include "planners/registry.hpp"

namespace fsweep {
namespace test_ompl_progress {  // not anonymous: unity builds put it beside other test files' helpers

/// A reachable query on a 30x30 map with a quarter of its cells blocked.
struct Query {
  KnownMap known = testing::random_known_map(30, 30, 0.25, 5);
  PlanRequest request;
  Query() {
    Rng rng = make_rng(3, "ompl_progress_query");
    const auto astar = make_planner("astar", nullptr);
    do {
      request.start = testing::random_free_cell(known, rng);
      request.goal = testing::random_free_cell(known, rng);
      request.seed = 17;
    } while (request.start == request.goal || astar->plan(known, request).status != PlanStatus::Success);
  }
};

/// The value of property `name` in sample `s` of `p`.
std::string value_of(const PlanProgress& p, std::size_t s, const std::string& name) {
  for (std::size_t i = 0; i < p.properties.size(); ++i) {
    if (p.properties[i] == name) return p.samples.at(s).values.at(i);
  }
  return "(no property " + name + ")";
}

TEST(OmplProgress, SamplingLeavesIterationBoundedResultsUnchanged) {
  // The single-threaded anytime planners, each ended by its iteration budget: the same path and
  // validity checks with and without samples, which hold every property the planner declares.
  const Query query;
  const std::vector<std::pair<const char*, std::vector<std::string>>> planners{
      {"ompl:RRTstar", {"best cost REAL", "iterations INTEGER"}},
      {"ompl:InformedRRTstar", {"best cost REAL", "iterations INTEGER"}},
      {"ompl:BITstar",
       {"best cost DOUBLE", "current free states INTEGER", "current graph vertices INTEGER",
        "edge collision checks INTEGER", "nearest neighbour calls INTEGER",
        "number of segments in solution path INTEGER", "state collision checks INTEGER"}},
      {"ompl:LazyPRMstar",
       {"best cost REAL", "edge count INTEGER", "iterations INTEGER", "milestone count INTEGER"}},
  };
  for (const auto& [name, properties] : planners) {
    const auto planner = make_planner(name, {{"time_limit_s", 5.0}, {"max_iterations", 1500}});
    PlanRequest plain = query.request;
    PlanRequest sampled = query.request;
    sampled.progress_interval_s = 1e-4;
    const PlanResult a = planner->plan(query.known, plain);
    const PlanResult b = planner->plan(query.known, sampled);
    ASSERT_EQ(a.status, PlanStatus::Success) << name;
    EXPECT_EQ(a.status, b.status) << name;
    EXPECT_EQ(a.path, b.path) << name;
    EXPECT_EQ(a.expansions, b.expansions) << name;
    EXPECT_TRUE(a.progress.properties.empty() && a.progress.samples.empty()) << name;  // not asked for

    const PlanProgress& p = b.progress;
    EXPECT_EQ(p.properties, properties) << name;
    ASSERT_GE(p.samples.size(), 2U) << name;  // the first check and the end of the solve at least
    for (std::size_t s = 0; s < p.samples.size(); ++s) {
      EXPECT_EQ(p.samples[s].values.size(), properties.size()) << name;
      if (s > 0) {
        EXPECT_GT(p.samples[s].time_s, p.samples[s - 1].time_s) << name;
      }
    }
    EXPECT_GE(p.samples.front().time_s, 0.0);
    EXPECT_LT(p.samples.back().time_s, b.time_s);
    // The best cost is read live: none before the first path, the solution's cost at the end.
    const std::string cost = properties.front();
    EXPECT_EQ(std::stod(value_of(p, 0, cost)), std::numeric_limits<double>::infinity()) << name;
    const double last_cost = std::stod(value_of(p, p.samples.size() - 1, cost));
    EXPECT_TRUE(std::isfinite(last_cost)) << name;
    EXPECT_GT(last_cost, 0.0) << name;
  }
}

TEST(OmplProgress, TwoThreadedPlannerIsSampledOnlyWhenItsSolveReturns) {
  // PRMstar's solution thread writes its best cost while the roadmap grows: one sample, at the end.
  const Query query;
  const auto planner = make_planner("ompl:PRMstar", {{"time_limit_s", 0.05}});
  PlanRequest r = query.request;
  r.progress_interval_s = 1e-4;
  const PlanResult result = planner->plan(query.known, r);
  ASSERT_EQ(result.status, PlanStatus::Success);
  EXPECT_EQ(result.progress.properties,
            (std::vector<std::string>{"best cost REAL", "edge count INTEGER", "iterations INTEGER",
                                      "milestone count INTEGER"}));
  ASSERT_EQ(result.progress.samples.size(), 1U);
  EXPECT_GE(result.progress.samples[0].time_s, 0.05);  // after the whole budget
  EXPECT_TRUE(std::isfinite(std::stod(value_of(result.progress, 0, "best cost REAL"))));
}

TEST(OmplProgress, PlannersWithoutProgressPropertiesReportNone) {
  const Query query;
  for (const char* name : {"ompl:RRTConnect", "ompl:KPIECE1", "astar", "lattice"}) {
    PlanRequest r = query.request;
    r.progress_interval_s = 1e-4;
    const PlanResult result = make_planner(name, nullptr)->plan(query.known, r);
    EXPECT_EQ(result.status, PlanStatus::Success) << name;
    EXPECT_TRUE(result.progress.properties.empty()) << name;
    EXPECT_TRUE(result.progress.samples.empty()) << name;
  }
}

}  // namespace test_ompl_progress
}  // namespace fsweep
