#include "planners/budget_params.hpp"

#include <nlohmann/json.hpp>

#include "core/config_error.hpp"

namespace fsweep {
inline namespace planners {

SearchBudget budget_from_json(const nlohmann::json& j, const std::string& where) {
  SearchBudget budget;
  if (const auto it = j.find(kTimeLimitKey); it != j.end()) {
    if (!it->is_number()) {
      throw ConfigError(where + "/" + std::string(kTimeLimitKey),
                        "expected a number of seconds > 0, got " + it->dump());
    }
    budget.time_limit_s = it->get<double>();
  }
  if (const auto it = j.find(kMaxExpansionsKey); it != j.end()) {
    if (!it->is_number_integer()) {
      throw ConfigError(where + "/" + std::string(kMaxExpansionsKey),
                        "expected an integer >= 0, got " + it->dump());
    }
    budget.max_expansions = it->get<long>();
  }
  const std::vector<std::string> violations = budget_violations(budget.time_limit_s, budget.max_expansions);
  if (!violations.empty()) throw ConfigError(where, join_names(violations));
  return budget;
}

std::vector<std::string> budget_violations(double time_limit_s, long max_expansions) {
  std::vector<std::string> violations;
  if (!(time_limit_s > 0.0)) {
    violations.push_back("time_limit_s must be a number of seconds > 0, got " + std::to_string(time_limit_s));
  }
  if (max_expansions < 0) {
    violations.push_back("max_expansions must be >= 0 (0: no limit), got " + std::to_string(max_expansions));
  }
  return violations;
}

}  // namespace planners
}  // namespace fsweep
