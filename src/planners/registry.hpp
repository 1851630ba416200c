#pragma once
/// @file registry.hpp
/// Planner names to factories. Filled explicitly in src/planners/register_all.cpp; the same
/// registry serves JSON, the command line and the tests.

#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "planners/planner.hpp"

namespace fsweep {
inline namespace planners {

/// Makes planner `name` with `params` (a JSON object; unknown keys are errors). Throws
/// ConfigError at `where` for an unknown name (listing the known ones), or at `where`/params
/// for bad parameters. `params` may be null (all defaults).
[[nodiscard]] std::unique_ptr<Planner> make_planner(const std::string& name, const nlohmann::json& params,
                                                    const std::string& where = "planner");

/// Every registered planner name, sorted.
[[nodiscard]] std::vector<std::string> planner_names();

/// The declared capabilities of planner `name`, or nullopt if no planner of that name is
/// registered.
[[nodiscard]] std::optional<PlannerCapabilities> planner_capabilities(std::string_view name);

}  // namespace planners
}  // namespace fsweep
