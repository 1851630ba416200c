#pragma once
/// @file budget_params.hpp
/// The query budget of the grid and lattice planners' params: `time_limit_s` (wall time of one
/// query's search, seconds > 0; null, the default: none) and `max_expansions` (states one query
/// may settle, an integer >= 0; 0, the default: none). The OMPL planners have their own
/// `time_limit_s` and `max_iterations` (ompl_planner.hpp).

#include <string>

#include "core/params.hpp"

namespace fsweep {
inline namespace planners {

/// Declares the budget of a params struct P with members `double time_limit_s` (+infinity:
/// none, written as JSON null) and `long max_expansions` (0: none), what each counts said by
/// `expansions_doc` (e.g. "cells one query may settle").
template <class P>
void declare_budget(ParamDecl<P>& d, const std::string& expansions_doc) {
  d.number_or_none("time_limit_s", &P::time_limit_s,
                   "wall time of one query's search; null: none (a query that runs out ends as Timeout)")
      .above(0)
      .unit("s");
  d.integer("max_expansions", &P::max_expansions,
            expansions_doc + "; 0: none (a query that runs out ends as Timeout)")
      .at_least(0);
}

}  // namespace planners
}  // namespace fsweep
