/// @file register_all.cpp
/// The one place where strategies are registered.

#include <algorithm>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>

#include "core/config_error.hpp"
#include "strategies/energy_aware.hpp"
#include "strategies/gbl.hpp"
#include "strategies/heuristics.hpp"
#include "strategies/mcdm.hpp"
#include "strategies/orientation.hpp"
#include "strategies/random_frontier.hpp"
#include "strategies/registry.hpp"
#include "strategies/target_seeking.hpp"
#include "strategies/widest_frontier.hpp"

namespace fsweep {
inline namespace strategies {
namespace {

struct Entry {
  std::function<std::unique_ptr<Strategy>(const nlohmann::json&, std::uint64_t, const std::string&)> make;
  std::function<nlohmann::json(const nlohmann::json&)> resolve;
};

const std::map<std::string, Entry>& table() {
  static const std::map<std::string, Entry> entries = {
      {"energy_aware",
       {[](const nlohmann::json& p, std::uint64_t, const std::string& where) -> std::unique_ptr<Strategy> {
          return std::make_unique<EnergyAware>("energy_aware", energy_aware_params_from_json(p, where));
        },
        [](const nlohmann::json& p) { return nlohmann::json(energy_aware_params_from_json(p, "")); }}},
      {"closest_frontier",
       {[](const nlohmann::json& p, std::uint64_t, const std::string& where) -> std::unique_ptr<Strategy> {
          EnergyAwareParams ea;
          ea.w1 = 1.0;
          ea.w2 = ea.w3 = ea.w4 = 0.0;
          if (!p.is_null()) {
            require_known_keys(p, {"distance"}, where);
            ea.distance = energy_aware_params_from_json(p, where).distance;
          }
          return std::make_unique<EnergyAware>("closest_frontier", ea);
        },
        [](const nlohmann::json& p) {
          std::string d = "path";
          if (!p.is_null() && p.contains("distance")) d = p.at("distance").get<std::string>();
          return nlohmann::json{{"distance", d}};
        }}},
      {"orientation",
       {[](const nlohmann::json& p, std::uint64_t, const std::string& where) -> std::unique_ptr<Strategy> {
          return std::make_unique<Orientation>(orientation_params_from_json(p, where));
        },
        [](const nlohmann::json& p) { return nlohmann::json(orientation_params_from_json(p, "")); }}},
      {"widest_frontier",
       {[](const nlohmann::json& p, std::uint64_t, const std::string& where) -> std::unique_ptr<Strategy> {
          widest_frontier_params_from_json(p, where);
          return std::make_unique<WidestFrontier>();
        },
        [](const nlohmann::json& p) {
          widest_frontier_params_from_json(p, "");
          return nlohmann::json::object();
        }}},
      {"gbl",
       {[](const nlohmann::json& p, std::uint64_t seed,
           const std::string& where) -> std::unique_ptr<Strategy> {
          return std::make_unique<Gbl>(gbl_params_from_json(p, where), seed);
        },
        [](const nlohmann::json& p) { return nlohmann::json(gbl_params_from_json(p, "")); }}},
      {"mcdm",
       {[](const nlohmann::json& p, std::uint64_t, const std::string& where) -> std::unique_ptr<Strategy> {
          return std::make_unique<Mcdm>(mcdm_params_from_json(p, where));
        },
        [](const nlohmann::json& p) { return nlohmann::json(mcdm_params_from_json(p, "")); }}},
      {"target_seeking",
       {[](const nlohmann::json& p, std::uint64_t, const std::string& where) -> std::unique_ptr<Strategy> {
          return std::make_unique<TargetSeeking>(target_seeking_params_from_json(p, where));
        },
        [](const nlohmann::json& p) { return nlohmann::json(target_seeking_params_from_json(p, "")); }}},
      {"random_frontier",
       {[](const nlohmann::json& p, std::uint64_t seed,
           const std::string& where) -> std::unique_ptr<Strategy> {
          random_frontier_params_from_json(p, where);
          return std::make_unique<RandomFrontier>(seed);
        },
        [](const nlohmann::json& p) {
          random_frontier_params_from_json(p, "");
          return nlohmann::json::object();
        }}},
  };
  return entries;
}

const Entry& find(const std::string& name, const std::string& where) {
  const auto& t = table();
  const auto it = t.find(name);
  if (it == t.end()) {
    throw ConfigError(where, "unknown strategy '" + name + "'; known: " + join_names(strategy_names()));
  }
  return it->second;
}

}  // namespace

std::unique_ptr<Strategy> make_strategy(const std::string& name, const nlohmann::json& params,
                                        std::uint64_t seed, const std::string& where) {
  // Heuristics apply to any strategy and are run by the engine (heuristics.hpp): validated
  // here, then taken out before the strategy's own parser sees the parameters.
  const Entry& entry = find(name, where);
  (void)heuristics_from_json(params, where + "/params");
  return entry.make(without_heuristics(params), seed, where + "/params");
}

std::vector<std::string> strategy_names() {
  std::vector<std::string> names;
  for (const auto& [name, entry] : table()) names.push_back(name);
  return names;
}

nlohmann::json resolved_strategy_params(const std::string& name, const nlohmann::json& params) {
  // "heuristics" is recorded (canonical order) whenever the key is given, even as [], and
  // omitted when absent: run keys and columns of configurations without the key are unchanged,
  // and every configuration of a sweep over [[], ["rr"], ...] has the column.
  nlohmann::json resolved = find(name, "strategy").resolve(without_heuristics(params));
  if (params.is_object() && params.contains("heuristics")) {
    if (resolved.is_null()) resolved = nlohmann::json::object();
    resolved["heuristics"] = heuristics_to_json(heuristics_from_json(params, "strategy/params"));
  }
  return resolved;
}

}  // namespace strategies
}  // namespace fsweep
