#pragma once
/// @file beam_lidar.hpp
/// The beam model of Sensor (sensor.hpp, SensorModel::Beams): a fan of beams, each a ray walked
/// cell by cell from the robot's cell centre to the first obstacle or the end of its range.
/// Sensor is the type the rest of the code uses and dispatches to this class; the geometry
/// (beam directions, traversal, corners, range, order, noise) is specified in sensor.hpp.

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "core/random.hpp"
#include "world/grid.hpp"
#include "world/known_map.hpp"
#include "world/scan_counts.hpp"
#include "world/world_map.hpp"

namespace fsweep {
inline namespace world {

/// The beams' directions and the scan scratch. Set-up O(beams); scan(), gain() and a visible()
/// cost O(beams x range cells) at most. Copyable value type: copies share the directions and
/// each has its own scratch, so one instance must not be used from two threads at once (gain()
/// too: it uses the scratch), but copies may.
class BeamLidar {
 public:
  BeamLidar() = default;
  /// `beams` >= 1 beams spread over `fov_deg` in (0, 360]. A cell is in range when the squared
  /// distance between its centre and the robot's cell centre is <= `squared_range_limit`
  /// (cells², the slack of the grid model's range rule included); a beam is
  /// sqrt(squared_range_limit) cells long. Throws std::invalid_argument on other values.
  BeamLidar(int beams, double fov_deg, double squared_range_limit);

  /// Number of beams (0 for a default-constructed instance).
  [[nodiscard]] int beams() const { return offsets_ ? static_cast<int>(offsets_->size()) : 0; }
  /// Direction of beam i relative to the heading (radians, clockwise on screen), i in [0, beams()).
  [[nodiscard]] double offset_rad(int i) const { return (*offsets_)[static_cast<std::size_t>(i)]; }

  /// Sensor::scan() of the beam model: reveals the cells the beams reach, in beam order and
  /// along each beam in the order entered (each cell at its first visit); a visited unknown cell
  /// other than the robot's is missed with probability `miss_probability`, one draw per cell
  /// in that order. The span stays valid until the next call.
  std::span<const int> scan(const WorldMap& truth, KnownMap& known, Cell at, double heading_rad,
                            double miss_probability, Rng& rng);

  /// Sensor::gain() of the beam model: the distinct cells the beams reach on `known` (known
  /// occupied cells and the map's edge stop a beam, unknown cells do not), by state.
  [[nodiscard]] ScanCounts gain(const KnownMap& known, Cell at, double heading_rad) const;

  /// True when a noiseless scan() from `at` facing `heading_rad` on `truth` would reveal
  /// `target` into an all-unknown map. Walks only the beams whose direction meets the target's
  /// square.
  [[nodiscard]] bool visible(const WorldMap& truth, Cell at, Cell target, double heading_rad) const;

 private:
  /// Calls enter(dx, dy) for every cell beam `beam` reaches from `at` facing `heading_rad` on a
  /// width x height grid with blocked(index) as the obstacle test (the map's edge blocks too),
  /// in the order entered; cells off the map or out of range are not passed. enter() returns
  /// false to end the beam. Defined in beam_lidar.cpp, the only place it is used.
  template <typename Blocked, typename Enter>
  void walk(int width, int height, Cell at, double heading_rad, int beam, Blocked&& blocked,
            Enter&& enter) const;

  /// Sets the scratch bit of offset (dx, dy) (in range); false when it was already set.
  bool mark(int dx, int dy) const;
  /// Clears the bits set by mark() since the last call.
  void clear_marks() const;

  std::shared_ptr<const std::vector<double>> offsets_;  // by beam; null when default-constructed
  double first_rad_ = 0.0;                              // offset of beam 0 (radians)
  double step_rad_ = 0.0;                               // spacing of the beams (radians)
  double squared_limit_ = 0.0;                          // cells²
  double length_ = 0.0;                                 // sqrt(squared_limit_), cells
  int reach_ = 0;                                       // cells in range have |dx|, |dy| <= reach_
  std::vector<int> revealed_;
  /// Scratch: one bit per offset of the (2 reach_ + 1)² box, allocated by the first mark(); all
  /// zero between calls.
  mutable std::vector<std::uint64_t> marks_;
  /// The bits mark() set, by position, for clear_marks().
  mutable std::vector<std::uint32_t> marked_;
};

}  // namespace world
}  // namespace fsweep
