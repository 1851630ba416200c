#pragma once
/// @file run_setup.hpp
/// What never changes during a run: the spec and the ground truth the Simulation derives from it
/// once (reachable and observable cells, resolved loop settings). A run and all its forks share
/// one RunSetup through std::shared_ptr<const RunSetup>, so a fork copies none of it.

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "sim/reveal_bound.hpp"
#include "sim/run_spec.hpp"
#include "world/grid.hpp"
#include "world/sensor.hpp"
#include "world/world_map.hpp"

namespace fsweep {
inline namespace sim {

/// "(x, y)": a cell in error messages and end details.
[[nodiscard]] std::string cell_text(Cell c);

/// Resolves `"target": "random"` in strategy params (any strategy with a "target" key, e.g.
/// target_seeking): returns a copy with "target" set to [x, y], a cell drawn uniformly among the
/// nonzero cells of `reachable` (free cells reachable from the start on the true map) other
/// than `start`, in row-major order, with the stream "target" of `seed` (src/core/random.hpp).
/// Params without that value are returned unchanged. Throws ConfigError
/// ("strategy/params/target") when no candidate cell exists.
[[nodiscard]] nlohmann::json resolve_random_target(const nlohmann::json& strategy_params,
                                                   const Grid<std::uint8_t>& reachable, Cell start,
                                                   std::uint64_t seed);

/// The observable cells of `map` for a robot whose reachable free cells are `reachable`
/// (reachable_free()): those cells plus their 4-neighbours in the grid, flagged 1. Equals the
/// cells that a scan (sensor.hpp, range >= one diagonal cell, any heading) from some cell of
/// `reachable` can see; see RunMetrics::completeness. O(cells).
[[nodiscard]] Grid<std::uint8_t> observable_cells(const WorldMap& map, const Grid<std::uint8_t>& reachable);

/// The immutable part of one run. Built by the Simulation's constructor, then only read.
struct RunSetup {
  /// Checks the map (given, start cell free; ConfigError "map" / "map start") and derives the
  /// ground truth and the loop settings. `stop_cell` is left empty: the Simulation resolves it
  /// (stop_cell_of()) after the checks that come before it.
  explicit RunSetup(const RunSpec& run_spec);

  /// The true map (shared with the spec).
  [[nodiscard]] const WorldMap& map() const { return *spec.map; }
  [[nodiscard]] bool allow_corner_cutting() const { return spec.robot.allow_corner_cutting; }

  RunSpec spec;
  /// Metres per cell of the map.
  double resolution_m = 1.0;
  /// Free cells reachable from the start on the true map (reachable_free(), the run's corner
  /// rule), flagged 1; `reachable_count` of them. The denominator of coverage.
  Grid<std::uint8_t> reachable;
  int reachable_count = 0;
  /// observable_cells() of `reachable`; `observable_count` of them. The denominator of
  /// completeness.
  Grid<std::uint8_t> observable;
  int observable_count = 0;
  /// SimParams resolved: cluster split length (metres), progress interval (metres), step cap.
  double cluster_max_length_m = 0.0;
  double progress_step_m = 1.0;
  long max_steps = 0;
  /// SimParams::stop_at_cell, resolved ("random" drawn); empty without one.
  std::optional<Cell> stop_cell;

  /// The geometry of the coverage target's look-ahead bound (reveal_bound.hpp) for a robot docked
  /// at `dock` (the run's dock, the same on every call): built on the first call, which only the
  /// weight search and its check make (it costs about a sixth of a run on street grids), and
  /// shared by the run and its forks. Thread-safe.
  [[nodiscard]] const RevealGeometry& reveal(Cell dock) const;

  /// Makes sight() return a SightTable of this run's map for `sensor` (a sensor of the run's own
  /// parameters; Sensor::sight_table(), so none for a beam sensor or a table too large) from now
  /// on, for the run and its forks. Thread-safe; later calls change nothing.
  void keep_sight(const Sensor& sensor) const;
  /// The table keep_sight() made, filled by the scans of the run and its forks (Belief::sense);
  /// null before (or without one): scans sweep. Thread-safe.
  [[nodiscard]] SightTable* sight() const { return sight_->table.load(std::memory_order_acquire); }

 private:
  struct LazyReveal {
    std::once_flag once;
    RevealGeometry geometry;
  };
  std::shared_ptr<LazyReveal> reveal_ = std::make_shared<LazyReveal>();
  struct LazySight {
    std::once_flag once;
    std::unique_ptr<SightTable> owned;
    std::atomic<SightTable*> table{nullptr};
  };
  std::shared_ptr<LazySight> sight_ = std::make_shared<LazySight>();
};

/// SimParams::stop_at_cell of `setup.spec`, with "random" drawn as resolve_random_target() draws
/// (ConfigError "sim/stop_at_cell" when no cell can be drawn); empty without one.
[[nodiscard]] std::optional<Cell> stop_cell_of(const RunSetup& setup);

/// Throws ConfigError ("robot/sensor/range_m") when the sensor range of `setup.spec` is below one
/// diagonal cell: the robot must see its 8 neighbours (RunMetrics::completeness relies on it).
void check_sensor_range(const RunSetup& setup);

/// Length (metres) of the shortest path from the map's start to `target` on the fully known
/// true map (the run's corner rule, octile steps); 0 when `target` is not reachable or not free.
[[nodiscard]] double shortest_path_from_start_m(const RunSetup& setup, Cell target);

}  // namespace sim
}  // namespace fsweep
