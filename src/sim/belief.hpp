#pragma once
/// @file belief.hpp
/// The belief part of a Simulation: what the robot knows of the world and what it derived from
/// it (frontiers, distances from the dock, dropped goals, how much of the ground truth it has
/// seen). A value: copying it forks what the robot knows.

#include <cstdint>
#include <span>
#include <vector>

#include "core/random.hpp"
#include "sim/dock_field.hpp"
#include "sim/grid_distance_oracle.hpp"
#include "sim/run_setup.hpp"
#include "world/frontiers.hpp"
#include "world/known_map.hpp"
#include "world/sensor.hpp"

namespace fsweep {
inline namespace sim {

class Belief {
 public:
  Belief() = default;
  /// Nothing known yet on the map of `setup`; the sensor's noise comes from the stream "sensor"
  /// of the run seed.
  explicit Belief(const RunSetup& setup);

  /// Scans with `sensor` from `at` facing `heading` (0..7) on the true map and takes in what it
  /// reveals: the known map, the frontiers, the dock field (started once `dock` is known free,
  /// then brought up to date on the first dock query of a decision), the ground-truth counts.
  /// Returns the number of cells revealed.
  int sense(Sensor& sensor, const RunSetup& setup, Cell at, int heading, Cell dock);

  [[nodiscard]] const KnownMap& known() const { return known_; }
  [[nodiscard]] const FrontierMap& frontiers() const { return frontiers_; }

  /// Frontier clusters of the goals not dropped (FrontierMap::clusters, split at the setup's
  /// `cluster_max_length_m`), kept up to date from what each scan revealed (FrontierClusters).
  /// The reference stays valid until the next call or scan.
  [[nodiscard]] const std::vector<FrontierCluster>& clusters();

  /// The distance oracle of one decision, from `robot` and `dock`, searching in `scratch`. It
  /// refers to this belief (the known map and the dock field): use it for that decision only,
  /// and do not sense while it lives.
  [[nodiscard]] GridDistanceOracle distance_oracle(const RunSetup& setup, Cell robot, Cell dock,
                                                   DistanceScratch& scratch);

  /// Never offer `goal` to a strategy again (unobservable, or no path found).
  void drop(Cell goal);

  /// True when some frontier cell not dropped is reachable from `from` over known free cells
  /// (read from the dock field when it is built and reaches `from`, which it brings up to date;
  /// else searched in `scratch`, as the decisions' searches; `dock` as for distance_oracle()).
  [[nodiscard]] bool frontier_reachable_from(Cell from, Cell dock, const RunSetup& setup,
                                             DistanceScratch& scratch);

  /// Known reachable free cells / reachable free cells of `setup` (1 when there are none).
  [[nodiscard]] double coverage(const RunSetup& setup) const;
  /// Known observable cells / observable cells of `setup` (1 when there are none).
  [[nodiscard]] double completeness(const RunSetup& setup) const;
  /// Known free cells reachable from the start (the numerator of coverage()).
  [[nodiscard]] int known_reachable() const { return known_reachable_; }
  /// Reachable free cells still unknown.
  [[nodiscard]] int unknown_reachable(const RunSetup& setup) const {
    return setup.reachable_count - known_reachable_;
  }

  /// The reachable cells not yet known free, counted per bin of `reveal` (RevealGeometry::bin),
  /// for the coverage target's bound: counted on the first call, then kept up to date by every
  /// scan (here and in copies). `reveal` must be the same on every call. The first call writes
  /// the counts: not to be made from two threads at once on one Belief.
  [[nodiscard]] std::span<const int> unknown_by_bin(const RevealGeometry& reveal) const;

 private:
  KnownMap known_;
  FrontierMap frontiers_;
  FrontierClusters clusters_;
  /// The sensor's noise stream (used only when SensorParams::miss_probability > 0).
  Rng sensor_rng_;
  DockField dock_field_;
  /// Marks as excluded (as dropped_) the cells within SimParams::target_margin_m of the newly
  /// known occupied cells among `revealed`.
  void keep_margin(const RunSetup& setup, std::span<const int> revealed);

  /// One flag per cell: a goal dropped for good, or too close to a known obstacle
  /// (SimParams::target_margin_m).
  std::vector<std::uint8_t> dropped_;
  int known_reachable_ = 0;
  int known_observable_ = 0;
  /// unknown_by_bin(): the geometry counted by (null before the first call) and the counts.
  mutable const RevealGeometry* reveal_ = nullptr;
  mutable std::vector<int> unknown_by_bin_;
};

}  // namespace sim
}  // namespace fsweep
