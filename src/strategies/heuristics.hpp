#pragma once
/// @file heuristics.hpp
/// Heuristics that apply to any strategy (Holz, Basilico, Amigoni 2010, section IV-D), set in
/// a strategy's JSON parameters as `"heuristics": ["rr", "seg"]` and applied by the engine
/// (src/sim/simulation.cpp), not by the strategy:
/// - `rr`, repetitive re-checking: while travelling to a goal, after every cell step, the goal
///   is re-checked; once it is no longer worth reaching the robot stops and decides again.
/// - `seg`, map segmentation: the known free space is split into rooms
///   (src/world/segmentation.hpp) and the candidates are restricted to the robot's current
///   segment whenever that segment holds any.
///
/// Because `heuristics` is an ordinary strategy parameter, sweeps vary it like any other
/// (`"params": {"heuristics": [[], ["rr"], ["seg"], ["rr", "seg"]]}`); make_strategy() and
/// resolved_strategy_params() (src/strategies/registry.hpp) take it out before the strategy's own
/// parser sees the parameters.

#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "strategies/sensing_region.hpp"
#include "strategies/strategy.hpp"

namespace fsweep {
inline namespace strategies {

/// The heuristics of one run. Default: none.
struct Heuristics {
  /// `rr`: repetitive re-checking of the goal while travelling.
  bool recheck = false;
  /// `seg`: candidates restricted to the robot's current map segment.
  bool segment = false;
  [[nodiscard]] bool any() const { return recheck || segment; }
  friend bool operator==(const Heuristics&, const Heuristics&) = default;
};

/// The heuristic names, in canonical order: "rr", "seg".
[[nodiscard]] std::vector<std::string> heuristic_names();

/// Reads `params["heuristics"]` of a strategy's parameters (`params` may be null or an object
/// without that key: no heuristics). The value must be a list of distinct names from
/// heuristic_names(), in any order. Throws ConfigError at `where` + "/heuristics" for anything
/// else: not a list, a non-string item, an unknown name (listing the known ones), a name given
/// twice. `where` is the JSON path of the parameter object.
[[nodiscard]] Heuristics heuristics_from_json(const nlohmann::json& params, const std::string& where);

/// The canonical JSON form: the names of the heuristics that are on, in heuristic_names()
/// order (an empty list for none).
[[nodiscard]] nlohmann::json heuristics_to_json(const Heuristics& h);

/// Short text for labels: the names joined with "+" ("rr+seg"), empty for none.
[[nodiscard]] std::string heuristics_text(const Heuristics& h);

/// `params` without its "heuristics" key, as the strategy's own parser must see it: `params`
/// itself when the key is absent (or `params` is not an object), else a copy without the key,
/// which becomes null when nothing else is left (so {"heuristics": [...]} means the strategy's
/// defaults, exactly as a missing params object).
[[nodiscard]] nlohmann::json without_heuristics(const nlohmann::json& params);

/// For strategies that read frontier cells rather than obs.clusters (the sensing-region rules
/// of orientation and widest_frontier): when obs.segment_mask is set (the `seg` heuristic
/// restricts this decision), keeps in `region.inside` and `region.outside` only the cells of
/// the robot's segment, unless none of either list is in it; then, and when the mask is null,
/// leaves `region` unchanged. Order is kept.
void restrict_to_segment(const Observation& obs, SensingRegion& region);

}  // namespace strategies
}  // namespace fsweep
