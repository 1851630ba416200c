#pragma once
/// @file register_all.hpp
/// The planner table behind registry.hpp. One explicit list in register_all.cpp (the OMPL
/// planners come from their own one list, ompl_planner_kinds()); no static-initialisation
/// self-registration.

#include <functional>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <span>
#include <string>
#include <string_view>

#include "planners/planner.hpp"

namespace fsweep {
inline namespace planners {

/// One registered planner: its name, its declared capabilities and a factory taking the
/// `params` object (may be null) and the JSON path for error messages.
struct PlannerEntry {
  std::string_view name;
  PlannerCapabilities capabilities;
  std::function<std::unique_ptr<Planner>(const nlohmann::json& params, const std::string& where)> make;
};

/// Every registered planner, in table order (names are unique).
[[nodiscard]] std::span<const PlannerEntry> planner_table();

}  // namespace planners
}  // namespace fsweep
