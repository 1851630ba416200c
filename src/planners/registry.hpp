#pragma once
/// @file registry.hpp
/// The planner registry (core/registry.hpp), filled explicitly in src/planners/register_all.cpp;
/// the same registry serves JSON, the command line (`fsweep describe planner`) and the tests.

#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/registry.hpp"
#include "planners/planner.hpp"

namespace fsweep {
inline namespace planners {

using PlannerRegistry = Registry<std::unique_ptr<Planner>>;
/// A planner resolved once: name, resolved params (every parameter), maker.
using PlannerConfig = PlannerRegistry::Configured;

/// Every registered planner.
[[nodiscard]] const PlannerRegistry& planner_registry();

/// Resolves planner `name` with `params` (a JSON object; null for defaults). Throws ConfigError at
/// `where` for an unknown name (listing the known ones) and one ConfigError listing every bad
/// parameter at `params_where`/<key> (default `where`/params).
[[nodiscard]] PlannerConfig configure_planner(const std::string& name, const nlohmann::json& params,
                                              const std::string& where = "planner",
                                              const std::string& params_where = {});

/// configure_planner(name, params, where).make().
[[nodiscard]] std::unique_ptr<Planner> make_planner(const std::string& name, const nlohmann::json& params,
                                                    const std::string& where = "planner");

/// Every registered planner name, sorted.
[[nodiscard]] std::vector<std::string> planner_names();

/// The declared capabilities of planner `name` (registered beside it in register_all.cpp), or
/// nullopt if no planner of that name is registered.
[[nodiscard]] std::optional<PlannerCapabilities> planner_capabilities(std::string_view name);

/// The declared capabilities of planner `name`, or nullopt if no planner of that name is
/// registered.
[[nodiscard]] std::optional<PlannerCapabilities> planner_capabilities(std::string_view name);

}  // namespace planners
}  // namespace fsweep
