#include "strategies/heuristics.hpp"

#include <algorithm>

#include "core/config_error.hpp"

namespace fsweep {
inline namespace strategies {
namespace {

constexpr const char* kKey = "heuristics";

}  // namespace

std::vector<std::string> heuristic_names() { return {"rr", "seg"}; }

Heuristics heuristics_from_json(const nlohmann::json& params, const std::string& where) {
  Heuristics h;
  if (!params.is_object() || !params.contains(kKey)) return h;
  const std::string at = where + "/" + kKey;
  const auto& v = params.at(kKey);
  if (!v.is_array()) {
    throw ConfigError(at, "expected a list of heuristic names, e.g. [\"rr\", \"seg\"] or [], got " +
                              v.dump() + "; known: " + join_names(heuristic_names()) +
                              " (in a sweep file a single list is written as a list of lists: [[\"rr\"]])");
  }
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string item_at = at + "/" + std::to_string(i);
    if (!v[i].is_string()) {
      throw ConfigError(item_at, "expected a heuristic name, got " + v[i].dump() +
                                     "; known: " + join_names(heuristic_names()));
    }
    const std::string name = v[i].get<std::string>();
    bool* flag = nullptr;
    if (name == "rr") {
      flag = &h.recheck;
    } else if (name == "seg") {
      flag = &h.segment;
    } else {
      throw ConfigError(item_at, "unknown heuristic '" + name + "'; known: " + join_names(heuristic_names()));
    }
    if (*flag)
      throw ConfigError(item_at, "heuristic '" + name + "' given twice; allowed: each name at most once");
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

nlohmann::json without_heuristics(const nlohmann::json& params) {
  if (!params.is_object() || !params.contains(kKey)) return params;
  nlohmann::json rest = params;
  rest.erase(kKey);
  return rest.empty() ? nlohmann::json(nullptr) : rest;
}

void restrict_to_segment(const Observation& obs, SensingRegion& region) {
  if (obs.segment_mask == nullptr) return;
  const auto& mask = *obs.segment_mask;
  const auto in_segment = [&](int i) { return mask[static_cast<std::size_t>(i)] != 0; };
  if (std::none_of(region.inside.begin(), region.inside.end(), in_segment) &&
      std::none_of(region.outside.begin(), region.outside.end(), in_segment)) {
    return;
  }
  std::erase_if(region.inside, [&](int i) { return !in_segment(i); });
  std::erase_if(region.outside, [&](int i) { return !in_segment(i); });
}

}  // namespace strategies
}  // namespace fsweep
