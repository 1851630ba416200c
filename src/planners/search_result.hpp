#pragma once
/// @file search_result.hpp
/// A planner's SearchResult from a BestFirstSearch run (src/search/grid_search.hpp).

#include <cstddef>
#include <vector>

#include "planners/planner.hpp"
#include "search/grid_search.hpp"

namespace fsweep {
inline namespace planners {

/// The result of the run of `search` that ended with `outcome`: Timeout when the stop condition
/// ended it, NoPath when no goal state was reached, else Success with the cell of every state
/// from the start to the goal (`cell_of(state)`); `expansions` in every case.
template <typename Cost, typename CellOf>
[[nodiscard]] SearchResult search_result(const BestFirstSearchT<Cost>& search, const SearchOutcome& outcome,
                                         CellOf cell_of) {
  SearchResult result;
  result.expansions = outcome.expansions;
  if (outcome.goal < 0) {
    result.status = outcome.stopped ? PlanStatus::Timeout : PlanStatus::NoPath;
    return result;
  }
  result.status = PlanStatus::Success;
  // The parent chain backwards, written in place (one allocation).
  std::size_t cells = search.trace_back(outcome.goal, [](int /*state*/) {});
  result.path.resize(cells);
  (void)search.trace_back(outcome.goal, [&](int s) { result.path[--cells] = cell_of(s); });
  return result;
}

}  // namespace planners
}  // namespace fsweep
