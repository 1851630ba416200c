#pragma once
/// @file plan_bench.hpp
/// Every planner on the same queries of one fully known map, measured against the optimal
/// octile length: the library part of `fsweep plan-bench` (src/cli/plan_bench_command.cpp).
/// Queries come from a MovingAI scenario (with its optimal lengths) or are random reachable
/// pairs (optimal lengths from `astar`). No printing or files here.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "evaluation/plan_compare.hpp"
#include "planners/planner.hpp"
#include "world/energy_model.hpp"
#include "world/grid.hpp"
#include "world/known_map.hpp"
#include "world/map_loaders.hpp"

namespace fsweep {
inline namespace evaluation {

/// One benchmark query.
struct BenchQuery {
  Cell start;
  Cell goal;
  /// Optimal octile length (cells, no corner cutting); > 0 since start != goal.
  double optimal_cells = 0.0;
};

/// The scenario's queries whose optimal length is > 0 (0 marks unreachable in GPPC files).
[[nodiscard]] std::vector<BenchQuery> bench_queries_from_scenario(const std::vector<ScenarioQuery>& scenario);

/// Random reachable pairs (draw_compare_pairs with `options`; start headings are not used) with
/// their optimal lengths from `astar` under `options.allow_corner_cutting`.
[[nodiscard]] std::vector<BenchQuery> bench_queries_from_pairs(const KnownMap& known,
                                                               const PairDrawOptions& options);

/// What one planner returned for one query.
struct BenchPlan {
  PlanStatus status = PlanStatus::NoPath;
  /// Path length / optimal length (>= 1 up to rounding); 0 unless Success.
  double length_ratio = 0.0;
  double energy = 0.0;
  int turns = 0;
  double time_s = 0.0;
  /// Path length in cells (length_m / resolution_m: length_ratio's numerator); 0 unless Success.
  double length_cells = 0.0;
  /// The planner's progress properties (PlanResult::progress) when BenchSettings asks for them.
  PlanProgress progress;
};

/// The request every planner gets for query q: start heading 0, `energy`,
/// `allow_corner_cutting`, seed derive_seed(seed, "plan_bench") + q, `progress_interval_s`.
struct BenchSettings {
  EnergyModel energy;
  bool allow_corner_cutting = false;
  std::uint64_t seed = 1;
  /// PlanRequest::progress_interval_s: seconds between samples of the planners' progress
  /// properties (0: none).
  double progress_interval_s = 0.0;
};

/// Plans every query with every planner, in order. Result [planner][query].
[[nodiscard]] std::vector<std::vector<BenchPlan>> run_plan_bench(
    const KnownMap& known, const std::vector<BenchQuery>& queries,
    const std::vector<std::unique_ptr<Planner>>& planners, const BenchSettings& settings);

/// One planner's statistics over its queries (quantiles over solved queries only).
struct BenchSummary {
  int queries = 0;
  int solved = 0;
  int timeouts = 0;
  /// solved / queries.
  double success_rate = 0.0;
  SampleSummary length_ratio;
  SampleSummary energy;
  SampleSummary turns;
  /// Milliseconds per query, over all queries (failed ones included: they cost their budget).
  SampleSummary time_ms;
};

/// Statistics of one planner's row of run_plan_bench().
[[nodiscard]] BenchSummary summarize_plan_bench(const std::vector<BenchPlan>& plans);

}  // namespace evaluation
}  // namespace fsweep
