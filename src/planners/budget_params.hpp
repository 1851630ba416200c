#pragma once
/// @file budget_params.hpp
/// The budget keys of the grid and lattice planners' params objects: `time_limit_s` (wall time
/// of one query's search, seconds > 0; absent: none) and `max_expansions` (states one query may
/// settle, an integer >= 0; absent or 0: none). The OMPL planners have their own
/// `time_limit_s` and `max_iterations` (ompl_planner.hpp).

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "search/stop_condition.hpp"

namespace fsweep {
inline namespace planners {

inline constexpr std::string_view kTimeLimitKey = "time_limit_s";
inline constexpr std::string_view kMaxExpansionsKey = "max_expansions";

/// The budget keys of `j` (an object; other keys are the caller's to check), defaults for the
/// absent ones. Throws ConfigError at `where`/key for a wrong type or a value out of range.
[[nodiscard]] SearchBudget budget_from_json(const nlohmann::json& j, const std::string& where);

/// Every violation of the budget ranges, empty when valid.
[[nodiscard]] std::vector<std::string> budget_violations(double time_limit_s, long max_expansions);

}  // namespace planners
}  // namespace fsweep
