#include "planners/registry.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/config_error.hpp"
#include "planners/register_all.hpp"

namespace fsweep {
inline namespace planners {

std::unique_ptr<Planner> make_planner(const std::string& name, const nlohmann::json& params,
                                      const std::string& where) {
  for (const PlannerEntry& entry : planner_table()) {
    if (entry.name == name) return entry.make(params, where + "/params");
  }
  throw ConfigError(where, "unknown planner '" + name + "'; known planners: " + join_names(planner_names()));
}

std::vector<std::string> planner_names() {
  std::vector<std::string> names;
  for (const PlannerEntry& entry : planner_table()) names.emplace_back(entry.name);
  std::sort(names.begin(), names.end());
  return names;
}

std::optional<PlannerCapabilities> planner_capabilities(std::string_view name) {
  for (const PlannerEntry& entry : planner_table()) {
    if (entry.name == name) return entry.capabilities;
  }
  return std::nullopt;
}

}  // namespace planners
}  // namespace fsweep
