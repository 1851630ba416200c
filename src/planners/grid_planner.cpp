#include "planners/grid_planner.hpp"

#include <nlohmann/json.hpp>

#include "core/config_error.hpp"
#include "planners/budget_params.hpp"
#include "search/octile_grid.hpp"

namespace fsweep {
inline namespace planners {
namespace {

/// Search environment of one query: cells are states, octile moves in cells, the goal cell
/// ends the search; the heuristic is the octile distance for A* and 0 for Dijkstra.
class GridEnvironment {
 public:
  GridEnvironment(const KnownMap& known, Cell goal, bool use_heuristic, bool allow_corner_cutting)
      : known_(known),
        goal_(goal),
        goal_index_(known.index(goal)),
        width_(known.width()),
        use_heuristic_(use_heuristic),
        allow_corner_cutting_(allow_corner_cutting) {}

  [[nodiscard]] int state_count() const { return known_.size(); }
  [[nodiscard]] double heuristic(int state) const {
    return use_heuristic_ ? octile_distance(Cell{state % width_, state / width_}, goal_) : 0.0;
  }
  Visit visit(int state, double /*g*/) const { return state == goal_index_ ? Visit::Goal : Visit::Expand; }
  template <typename Sink>
  void for_each_successor(int state, Sink&& sink) const {
    for_each_octile_neighbour(known_, state, allow_corner_cutting_, sink);
  }

 private:
  const KnownMap& known_;
  Cell goal_;
  int goal_index_;
  int width_;
  bool use_heuristic_;
  bool allow_corner_cutting_;
};

}  // namespace

GridPlannerParams GridPlannerParams::from_json(const nlohmann::json& j, const std::string& where) {
  GridPlannerParams p;
  if (j.is_null()) return p;
  require_known_keys(j, {kTimeLimitKey, kMaxExpansionsKey}, where);
  const SearchBudget budget = budget_from_json(j, where);
  p.time_limit_s = budget.time_limit_s;
  p.max_expansions = budget.max_expansions;
  return p;
}

std::vector<std::string> GridPlannerParams::validate() const {
  return budget_violations(time_limit_s, max_expansions);
}

std::string GridPlanner::name() const { return kind_ == GridSearchKind::AStar ? "astar" : "dijkstra"; }

std::unique_ptr<Planner> GridPlanner::clone() const { return std::make_unique<GridPlanner>(kind_, params_); }

SearchResult GridPlanner::search(const KnownMap& known, const PlanRequest& request,
                                 const StopCondition& stop) {
  // 1. Search; start == goal settles the start as the goal (a one-cell path).
  GridEnvironment env(known, request.goal, kind_ == GridSearchKind::AStar, request.allow_corner_cutting);
  SearchLimits limits;
  limits.stop = stop;
  const SearchOutcome outcome = search_.run(env, known.index(request.start), limits);
  SearchResult result;
  result.expansions = outcome.expansions;
  if (outcome.goal < 0) {
    result.status = outcome.stopped ? PlanStatus::Timeout : PlanStatus::NoPath;
    return result;
  }
  // 2. Cells along the parents.
  result.status = PlanStatus::Success;
  const std::vector<int> states = search_.path_to(outcome.goal);
  result.path.reserve(states.size());
  for (const int s : states) result.path.push_back(known.cell(s));
  return result;
}

}  // namespace planners
}  // namespace fsweep
