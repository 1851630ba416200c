#pragma once
/// @file reproducibility.hpp
/// Whether a planner's runs repeat exactly for the same run seed, judged from its name and
/// parameters as a sweep's runs.csv records them (columns `planner` and `planner.<param>`).
/// `fsweep compare` (src/report/compare.hpp) compares reproducible runs cell by cell and
/// the others by quantiles.

#include <map>
#include <string>
#include <string_view>

namespace fsweep {
inline namespace planners {

/// True if runs with planner `planner` and parameters `params` give the same quality
/// metrics for the same run seed on the same build (docs/planners.md, the planner table's determinism
/// column), by the planner's declared Determinism (planner_capabilities() in registry.hpp):
/// - Always (the grid and lattice planners, `shortest_fewest_turns`): true;
/// - WithMaxIterations (the single-threaded OMPL planners): only with `max_iterations` > 0 (and
///   a time limit it reaches first), else they stop at the time limit: the anytime planners on
///   every query, RRTConnect and KPIECE1 on queries they cannot solve;
/// - Never (`ompl:PRMstar`): false.
/// `params` maps a parameter name without the `planner.` prefix (e.g. "max_iterations") to
/// its CSV text; a missing or empty entry is the planner's default (max_iterations 0 = none),
/// a text that is not an integer counts as unset. A name this build does not register gives
/// false: nothing is known about it, so its runs are only compared statistically.
[[nodiscard]] bool planner_reproducible(std::string_view planner,
                                        const std::map<std::string, std::string>& params);

}  // namespace planners
}  // namespace fsweep
