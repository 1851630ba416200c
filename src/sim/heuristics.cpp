#include "sim/heuristics.hpp"

#include "core/config_error.hpp"
#include "core/json_excerpt.hpp"

namespace fsweep {
inline namespace sim {

std::vector<std::string> heuristic_names() { return {"rr", "seg"}; }

Heuristics heuristics_from_json(const nlohmann::json& list, const std::string& where) {
  Heuristics h;
  if (list.is_null()) return h;
  if (!list.is_array()) {
    throw ConfigError(where, "expected a list of heuristic names, e.g. [\"rr\", \"seg\"] or [], got " +
                                 json_excerpt(list) + "; known: " + join_names(heuristic_names()));
  }
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string item_at = where + "/" + std::to_string(i);
    if (!list[i].is_string()) {
      throw ConfigError(item_at, "expected a heuristic name, got " + json_excerpt(list[i]) +
                                     "; known: " + join_names(heuristic_names()));
    }
    const std::string name = list[i].get<std::string>();
    bool* flag = nullptr;
    if (name == "rr") {
      flag = &h.recheck;
    } else if (name == "seg") {
      flag = &h.segment;
    } else {
      throw ConfigError(item_at, "unknown heuristic '" + name + "'; known: " + join_names(heuristic_names()));
    }
    if (*flag) {
      throw ConfigError(item_at, "heuristic '" + name + "' given twice; allowed: each name at most once");
    }
    *flag = true;
  }
  return h;
}

nlohmann::json heuristics_to_json(const Heuristics& h) {
  nlohmann::json out = nlohmann::json::array();
  if (h.recheck) out.push_back("rr");
  if (h.segment) out.push_back("seg");
  return out;
}

std::string heuristics_text(const Heuristics& h) {
  std::string s;
  for (const auto& name : heuristics_to_json(h)) s += (s.empty() ? "" : "+") + name.get<std::string>();
  return s;
}

}  // namespace sim
}  // namespace fsweep
