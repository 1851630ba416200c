#include "planners/registry.hpp"

#include <nlohmann/json.hpp>

namespace fsweep {
inline namespace planners {

PlannerConfig configure_planner(const std::string& name, const nlohmann::json& params,
                                const std::string& where, const std::string& params_where) {
  return planner_registry().configure(name, params, where, params_where);
}

std::unique_ptr<Planner> make_planner(const std::string& name, const nlohmann::json& params,
                                      const std::string& where) {
  return configure_planner(name, params, where).make();
}

std::vector<std::string> planner_names() { return planner_registry().names(); }

}  // namespace planners
}  // namespace fsweep
