#pragma once
/// @file heuristics.hpp
/// Heuristics that apply to any strategy (Holz, Basilico, Amigoni 2010, section IV-D). They are
/// a simulation setting (RunSpec::heuristics), applied by the engine (src/sim/simulation.cpp),
/// not by the strategy. In a sweep's strategy entry they sit beside "params":
/// `"heuristics": ["rr", "seg"]`, or a list of such lists to sweep them.
/// - `rr`, repetitive re-checking: while travelling to a goal, after every cell step, the goal
///   is re-checked; once it is no longer worth reaching the robot stops and decides again.
/// - `seg`, map segmentation: the known free space is split into rooms
///   (src/world/segmentation.hpp) and the candidates are restricted to the robot's current
///   segment whenever that segment holds any.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace fsweep {
inline namespace sim {

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

/// Reads a list of distinct names from heuristic_names(), in any order (null: none). Throws
/// ConfigError at `where` (the list's JSON path) for anything else: not a list, a non-string
/// item, an unknown name (listing the known ones), a name given twice.
[[nodiscard]] Heuristics heuristics_from_json(const nlohmann::json& list, const std::string& where);

/// The canonical JSON form: the names of the heuristics that are on, in heuristic_names()
/// order (an empty list for none).
[[nodiscard]] nlohmann::json heuristics_to_json(const Heuristics& h);

/// Short text for labels: the names joined with "+" ("rr+seg"), empty for none.
[[nodiscard]] std::string heuristics_text(const Heuristics& h);

}  // namespace sim
}  // namespace fsweep
