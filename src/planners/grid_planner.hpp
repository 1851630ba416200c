#pragma once
/// @file grid_planner.hpp
/// `dijkstra` and `astar`: optimal 8-connected planners over known-free cells with octile
/// costs (docs/architecture.md, "Plugins and their parameters"). Moves follow src/search/octile_grid.hpp (no
/// corner cutting unless PlanRequest::allow_corner_cutting), so lengths match MovingAI's optimal lengths.

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

/// Parameters of the grid planners. There are none yet: `{}` (or null) is the only valid
/// input and any key is a ConfigError. Tie-breaking is fixed, not a parameter: see
/// BestFirstSearch (smaller f, then larger g, then smaller cell index).
struct GridPlannerParams {};

/// Optimal grid planner. Keeps its search arrays between queries (not thread-safe).
///
/// Statuses: StartInvalid if the start is outside the grid or not known free; otherwise
/// GoalInvalid likewise for the goal; NoPath if the goal is not reachable through known-free
/// cells; Success otherwise (start == goal gives the one-cell path). Timeout never happens.
/// On Success, length, energy, stops and turns come from measure_path() (motion.hpp) from
/// PlanRequest::start_heading under PlanRequest::energy; `expansions` counts settled cells.
class GridPlanner final : public Planner {
 public:
  explicit GridPlanner(GridSearchKind kind, GridPlannerParams params = {}) : kind_(kind), params_(params) {}

  [[nodiscard]] std::string name() const override;
  [[nodiscard]] PlanResult plan(const KnownMap& known, const PlanRequest& request) override;
  [[nodiscard]] std::unique_ptr<Planner> clone() const override;

  [[nodiscard]] GridSearchKind kind() const { return kind_; }
  [[nodiscard]] const GridPlannerParams& params() const { return params_; }

 private:
  GridSearchKind kind_;
  GridPlannerParams params_;
  BestFirstSearch search_;
};

}  // namespace planners
}  // namespace fsweep
