#pragma once
/// @file scenario_check.hpp
/// Runs a planner on every query of a MovingAI scenario over the fully known map and compares
/// its lengths with the file's optimal lengths (the `fsweep plan` command prints the report).

#include <vector>

#include "planners/planner.hpp"
#include "world/map_loaders.hpp"
#include "world/world_map.hpp"

namespace fsweep {
inline namespace evaluation {

/// Relative tolerance of a length comparison; MovingAI v1 files print about 6 significant digits.
inline constexpr double kScenarioToleranceRel = 1e-5;

/// One query's outcome.
struct ScenarioQueryResult {
  /// The query as read from the file.
  ScenarioQuery query;
  /// The planner's status.
  PlanStatus status = PlanStatus::NoPath;
  /// Planned length in cells (length_m / resolution_m); 0 unless Success.
  double length_cells = 0.0;
  /// The file's optimal length (cells).
  double optimal_cells = 0.0;
  /// Optimal length 0 with start != goal: the GPPC convention for "unreachable".
  bool unreachable_expected = false;
  /// Success with a length within tolerance of the optimum, or NoPath when unreachable_expected.
  bool match = false;
  /// The planner's expansions and wall time (seconds) for this query.
  long expansions = 0;
  double time_s = 0.0;
};

/// All queries' outcomes and totals.
struct ScenarioReport {
  /// One entry per query, in file order.
  std::vector<ScenarioQueryResult> queries;
  /// Query counts: total = matches + mismatches.
  int total = 0;
  int matches = 0;
  int mismatches = 0;
  /// Queries with unreachable_expected (matched or not).
  int unreachable_expected = 0;
  /// Sum of the per-query expansions.
  long expansions = 0;
  /// Sum of the planner's per-query times (seconds).
  double plan_time_s = 0.0;
  /// Wall time of the whole check, including fully_known() (seconds).
  double wall_time_s = 0.0;
};

/// Plans every query on fully_known(map) with the request defaults (start heading 0, no corner
/// cutting) and compares lengths: a match is |length - optimal| <= tolerance_abs or
/// <= kScenarioToleranceRel * optimal. Throws ConfigError if a query names a map size
/// (width/height fields, when non-zero) different from `map`'s.
[[nodiscard]] ScenarioReport check_scenario(const WorldMap& map, const std::vector<ScenarioQuery>& queries,
                                            Planner& planner, double tolerance_abs = 1e-2);

}  // namespace evaluation
}  // namespace fsweep
