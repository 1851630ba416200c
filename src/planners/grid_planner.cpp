#include "planners/grid_planner.hpp"

#include <limits>
#include <nlohmann/json.hpp>

#include "core/config_error.hpp"
#include "planners/search_result.hpp"
#include "search/cell_indexer.hpp"
#include "search/octile_grid.hpp"

namespace fsweep {
inline namespace planners {
namespace {

/// One query's search with `search` over `Env`: the cells from start to goal, or the failure.
template <typename Env>
SearchResult search_grid(OctileSearch& search, const Env& env, const KnownMap& known, Cell start,
                         const StopCondition& stop) {
  SearchLimits limits;
  limits.stop = stop;
  const SearchOutcome outcome = search.run(env, known.index(start), limits);
  const CellIndexer cells(known.width());  // no division per path cell
  return search_result(search, outcome, [&cells](int s) { return cells.cell(s); });
}

}  // namespace

std::string GridPlanner::name() const { return kind_ == GridSearchKind::AStar ? "astar" : "dijkstra"; }

std::unique_ptr<Planner> GridPlanner::clone() const { return std::make_unique<GridPlanner>(kind_, params_); }

SearchResult GridPlanner::search(const KnownMap& known, const PlanRequest& request,
                                 const StopCondition& stop) {
  // Start == goal settles the start as the goal (a one-cell path).
  if (kind_ == GridSearchKind::AStar) {
    // The same search run before, to the goal (PathProbe): only a budget could end this one sooner.
    if (request.searched != nullptr && budget().time_limit_s == std::numeric_limits<double>::infinity() &&
        budget().max_expansions == 0) {
      return *request.searched;
    }
    return search_grid(search_,
                       OctileGoalEnvironment<true>(known, request.goal, request.allow_corner_cutting), known,
                       request.start, stop);
  }
  return search_grid(search_, OctileGoalEnvironment<false>(known, request.goal, request.allow_corner_cutting),
                     known, request.start, stop);
}

}  // namespace planners
}  // namespace fsweep
