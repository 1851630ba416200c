/// @file repetition_check.cpp
/// identical_repetition_warnings() (repetition_check.hpp).

#include "sweep/repetition_check.hpp"

#include <set>

#include "core/config_error.hpp"
#include "planners/registry.hpp"
#include "strategies/registry.hpp"

namespace fsweep {
inline namespace sweep {
namespace {

/// Names shown in a warning's lists at most.
constexpr std::size_t kListed = 6;

/// "a, b, c" of at most kListed names, then "and N more".
std::string listed(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size() && i < kListed; ++i) out += (i ? ", " : "") + names[i];
  if (names.size() > kListed) out += " and " + std::to_string(names.size() - kListed) + " more";
  return out;
}

/// True when the strategy configuration `params` of entry `e` draws from its seed.
bool seeded_strategy(const StrategyEntry& e, const nlohmann::json& params) {
  if (strategy_traits(e.name).seeded) return true;
  return params.is_object() && params.contains("target") && params["target"] == "random";
}

}  // namespace

std::vector<std::string> identical_repetition_warnings(const SweepPlan& plan) {
  if (plan.repetitions() < 2 || plan.sim().stop_at_random) return {};
  // 1. Per axis, the items with nothing random; a configuration is fixed when all of its are.
  std::vector<std::string> classes;
  for (const SweepMap& m : plan.maps()) {
    if (m.start_regions == nullptr && std::find(classes.begin(), classes.end(), m.map_class) == classes.end())
      classes.push_back(m.map_class);
  }
  std::vector<std::string> strategies;
  std::uint64_t fixed_combos = 0, combos = 0;
  for (const StrategyEntry& e : plan.strategies()) {
    if (e.search) continue;
    std::uint64_t fixed = 0;
    for (std::uint64_t k = 0; k < e.count(); ++k) fixed += seeded_strategy(e, e.params_at(k)) ? 0 : 1;
    combos += e.count();
    fixed_combos += fixed;
    if (fixed == e.count()) {
      strategies.push_back(e.label);
    } else if (fixed > 0) {
      strategies.push_back(e.label + " (" + std::to_string(fixed) + " of " + std::to_string(e.count()) + ")");
    }
  }
  std::vector<std::string> planners;
  for (const SweepPlanner& p : plan.planners()) {
    const auto caps = planner_capabilities(p.name);
    if (!caps || !caps->seeded) planners.push_back(p.name);
  }
  std::vector<std::string> robots;
  for (const RobotVariant& r : plan.robots()) {
    if (!(r.params.sensor.miss_probability > 0.0)) robots.push_back(r.label);
  }
  const std::uint64_t fixed = classes.size() * fixed_combos * planners.size() * robots.size();
  if (fixed == 0) return {};
  std::set<std::string> all_classes;
  for (const SweepMap& m : plan.maps()) all_classes.insert(m.map_class);
  const std::uint64_t total = all_classes.size() * combos * plan.planners().size() * plan.robots().size();
  // 2. One warning naming them.
  const std::string reps = std::to_string(plan.repetitions());
  std::string line =
      std::to_string(fixed) + " of " + std::to_string(total) +
      " configurations have nothing random in them (no sensor misses, a fixed start, no seeded "
      "strategy or planner), so their " +
      reps + " repetitions on a map instance will be " + reps +
      " copies of one run and summary.csv's n counts each run " + reps + " times: map classes " +
      listed(classes) + "; strategies " + listed(strategies) + "; planners " + listed(planners);
  if (plan.robots().size() > 1) line += "; robots " + listed(robots);
  line +=
      ". For repetitions that mean something, give the map generators several seeds (\"seeds\": {\"range\": "
      "[1, "
      "10]}) or a random start (start=random in a map's SPEC; not on free maps), or a sensor "
      "miss_probability; "
      "else set \"repetitions\": 1";
  return {line};
}

}  // namespace sweep
}  // namespace fsweep
