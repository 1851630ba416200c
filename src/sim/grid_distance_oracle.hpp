#pragma once
/// @file grid_distance_oracle.hpp
/// The engine's answer to strategies' distance queries: bounded one-to-many Dijkstra over
/// known free space from the robot and from the dock, cached for one decision.

#include <cstdint>
#include <optional>
#include <vector>

#include "planners/planner.hpp"
#include "search/distance_field.hpp"
#include "sim/dock_field.hpp"
#include "strategies/strategy.hpp"

namespace fsweep {
inline namespace sim {

/// The search arrays of GridDistanceOracle, kept from one decision to the next: allocating them
/// for every decision (a map-sized array per field) costs more than most decisions. Scratch,
/// not state: nothing in it outlives a decision but the allocation and the paths the decision's
/// probes found (for the journey right after it: probed_path()), so a copy starts empty (a
/// fork allocates its own arrays on its first decision instead of copying these) and
/// assignment keeps the target's arrays but drops its paths.
class DistanceScratch {
 public:
  DistanceScratch() = default;
  DistanceScratch(const DistanceScratch& /*other*/) {}
  DistanceScratch& operator=(const DistanceScratch& /*other*/) {
    probed_.clear();  // found on the map this scratch's simulation had before
    return *this;
  }
  DistanceScratch(DistanceScratch&&) noexcept = default;
  DistanceScratch& operator=(DistanceScratch&&) noexcept = default;
  ~DistanceScratch() = default;

  /// What a probe (GridDistanceOracle::probe_from_robot) of the last decision found from `start`
  /// to `goal` on `known` (this very map object, unchanged since) under the corner rule
  /// `allow_corner_cutting`: planner `astar`'s path and expansions (PathProbe), for
  /// PlanRequest::searched. Empty when no probe reached that goal so.
  [[nodiscard]] std::optional<SearchResult> probed_path(const KnownMap& known, Cell start, Cell goal,
                                                        bool allow_corner_cutting) const;

 private:
  friend class GridDistanceOracle;
  /// A probe's goal, its path (cell indices from the robot) and the cells it settled.
  struct Probed {
    int goal;
    std::vector<int> path;
    long expansions;
  };
  /// The one field of all of a decision's searches but the probes (from the robot or the dock:
  /// settle-all, nearest, watched), one after the other: 12 bytes a cell, instead of one field
  /// for each kind. The probes run in probe_ (16 bytes a cell, once a probe ran).
  DistanceField field_;
  /// What field_ holds that a later query may read again: the lengths from `source_` of the
  /// cells `cells_` up to `bound_m_` (< 0: nothing, as after a nearest, watched or probe search
  /// or at the start of a decision).
  Cell source_{};
  double bound_m_ = -1.0;
  std::vector<int> cells_;
  /// The probes' A* with its parents, and the paths it found in this decision: from
  /// `probed_from_` on the map of that instance_id() and revision() (KnownMap: its content), under
  /// that corner rule.
  PathProbe probe_;
  std::vector<Probed> probed_;
  Cell probed_from_{};
  std::uint64_t probed_map_ = 0;
  std::uint64_t probed_revision_ = 0;
  bool probed_corner_cutting_ = false;
};

/// One decision's oracle. It refers to the simulation's belief (Belief::distance_oracle()) and
/// to search arrays, and lives for that decision only: nothing keeps it (or a pointer into a
/// belief) between decisions, so copying a Simulation never has to fix up references. Not
/// copyable.
class GridDistanceOracle final : public DistanceOracle {
 public:
  /// An oracle over `known` from `robot` and `dock`, searching in `scratch` (whose cached
  /// fields it invalidates). `dock_field` (may be null or not ready()) is the simulation's
  /// field from the dock, brought up to date on the first dock query, so runs whose strategy
  /// never asks for dock distances never pay for it; without it, dock distances are searched
  /// like robot distances. All must outlive the oracle.
  GridDistanceOracle(const KnownMap& known, Cell robot, Cell dock, bool allow_corner_cutting,
                     DockField* dock_field, DistanceScratch& scratch);
  GridDistanceOracle(const GridDistanceOracle&) = delete;
  GridDistanceOracle& operator=(const GridDistanceOracle&) = delete;
  GridDistanceOracle(GridDistanceOracle&&) = delete;
  GridDistanceOracle& operator=(GridDistanceOracle&&) = delete;
  ~GridDistanceOracle() override = default;

  [[nodiscard]] std::vector<double> from_robot(std::span<const int> cells, double bound_m) override;
  [[nodiscard]] std::vector<double> from_dock(std::span<const int> cells, double bound_m) override;
  [[nodiscard]] int nearest_from_robot(std::span<const int> cells) override;
  void watch_from_robot(std::span<const int> cells, double bound_m, SettleWatcher& watcher) override;
  /// A* from the robot (PathProbe::compute_to): exact, so it reads as the robot's field would.
  /// A probe that reaches its cell keeps the path for the journey there
  /// (DistanceScratch::probed_path).
  [[nodiscard]] std::optional<double> probe_from_robot(int cell, double bound_m,
                                                       long max_expansions) override;
  /// The octile length (no path is shorter; exact, as the fields' costs are) and, when the dock
  /// field is up to date, the triangle bound d(dock, cell) - d(dock, robot) less a relative
  /// 1e-9 for its two roundings (+infinity when the robot reaches the dock but the dock does
  /// not reach `cell`).
  [[nodiscard]] std::vector<double> lower_bounds_from_robot(std::span<const int> cells) const override;

  /// Expansions of all searches of this oracle (the dock field's updates included).
  [[nodiscard]] long expansions() const { return expansions_; }

 private:
  /// The lengths from `source` to `cells` up to `bound_m` (+infinity beyond), from the field
  /// when it holds them, else by a search that stops once all of them are settled.
  std::vector<double> lookup(Cell source, std::span<const int> cells, double bound_m);

  const KnownMap& known_;
  Cell robot_;
  Cell dock_;
  bool corner_cutting_;
  DockField* dock_field_;
  DistanceScratch& scratch_;
  long expansions_ = 0;
};

}  // namespace sim
}  // namespace fsweep
