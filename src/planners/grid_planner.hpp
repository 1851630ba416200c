#pragma once
/// @file grid_planner.hpp
/// `dijkstra` and `astar`: optimal 8-connected planners over known-free cells with octile
/// costs (docs/dev/architecture.md, "Plugins and their parameters"). Moves follow src/search/octile_grid.hpp
/// (no corner cutting unless PlanRequest::allow_corner_cutting), so lengths match MovingAI's optimal lengths.

#include <limits>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "planners/planner.hpp"
#include "search/grid_search.hpp"

namespace fsweep {
inline namespace planners {

/// Which search a GridPlanner runs.
enum class GridSearchKind {
  /// Uniform-cost search (zero heuristic): registry name `dijkstra`.
  Dijkstra,
  /// A* with the octile distance to the goal (admissible and consistent): `astar`.
  AStar,
};

/// Parameters of the grid planners: only the query budget (declare_budget() in budget_params.hpp); any other
/// key is a ConfigError. Tie-breaking is fixed, not a parameter: see BestFirstSearch (smaller f, then larger
/// g, then smaller cell index).
struct GridPlannerParams {
  /// Wall time of one query's search (seconds, > 0); +infinity (the default, JSON null): none.
  double time_limit_s = std::numeric_limits<double>::infinity();
  /// Cells one query may settle (>= 0); 0 (the default): none.
  long max_expansions = 0;
};

/// Optimal grid planner. Keeps its search arrays between queries (not thread-safe).
///
/// Statuses (besides Planner::plan()'s endpoint checks): NoPath if the goal is not reachable
/// through known-free cells; Timeout if the time limit or the expansion budget ends the search
/// first (with `max_expansions` = n, a query that settles its goal as the n-th cell succeeds);
/// Success otherwise (start == goal gives the one-cell path). `expansions` counts settled cells.
class GridPlanner final : public Planner {
 public:
  /// Deterministic and length-optimal (fixed tie-breaking, an admissible heuristic).
  static constexpr PlannerCapabilities kCapabilities{Determinism::Always, true, false};

  explicit GridPlanner(GridSearchKind kind, GridPlannerParams params = {})
      : Planner(SearchBudget{params.time_limit_s, params.max_expansions}), kind_(kind), params_(params) {}

  [[nodiscard]] std::string name() const override;
  [[nodiscard]] std::unique_ptr<Planner> clone() const override;

  [[nodiscard]] GridSearchKind kind() const { return kind_; }
  [[nodiscard]] const GridPlannerParams& params() const { return params_; }

 protected:
  [[nodiscard]] SearchResult search(const KnownMap& known, const PlanRequest& request,
                                    const StopCondition& stop) override;

 private:
  GridSearchKind kind_;
  GridPlannerParams params_;
  OctileSearch search_;
};

}  // namespace planners
}  // namespace fsweep
