#pragma once
/// @file sensor.hpp
/// Omnidirectional range sensor with optional field of view and seeded per-cell misses.
///
/// Visibility rule (precise, tested in tests/world/test_sensor.cpp):
/// - Range: a cell is in range when the Euclidean distance between the centres of the robot's
///   cell and the target cell is <= range_m / resolution_m (cells). The boundary is included.
/// - Field of view: with fov_deg < 360 the direction to the target cell centre must lie within
///   +-fov_deg/2 of the heading (inclusive). The robot's own cell is always seen.
/// - Line of sight: the segment between the two cell centres is walked cell by cell
///   (Amanatides-Woo). Every cell the segment enters before the target must not be occupied.
///   Where the segment passes exactly through a grid corner it touches the two cells beside
///   the corner only at that point: it is blocked there only if both of those cells are
///   occupied (a diagonal gap between two occupied cells is opaque; a gap with one free side
///   is see-through). Occupied cells that are reached are themselves observed.
/// - Noise: with miss_probability p > 0 every visible, still unknown cell stays unknown with
///   probability p on this scan (drawn from the run's "sensor" stream in a fixed cell order).

#include <cstdint>
#include <span>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "engine/world/grid.hpp"
#include "engine/world/known_map.hpp"
#include "engine/world/random.hpp"
#include "engine/world/world_map.hpp"

namespace fsweep {

struct SensorParams {
  /// Sensing radius (metres), > 0.
  double range_m = 10.0;
  /// Field of view (degrees), in (0, 360]; 360 = omnidirectional.
  double fov_deg = 360.0;
  /// Probability that a visible unknown cell is missed on one scan, in [0, 1).
  double miss_probability = 0.0;
};

/// Reads {"range_m", "fov_deg", "miss_probability"}; throws ConfigError at `where`.
[[nodiscard]] SensorParams sensor_params_from_json(const nlohmann::json& j, const std::string& where);
void to_json(nlohmann::json& j, const SensorParams& p);

/// A sensor for one resolution. Precomputes, per target offset in range, the cells its line of
/// sight crosses, so a scan costs one table walk. Copyable value type.
class Sensor {
 public:
  Sensor() = default;
  Sensor(const SensorParams& params, double resolution_m);

  /// Scans from `at` facing `heading_rad` (radians, clockwise on screen from +x, as
  /// heading_angle()). Reveals visible unknown cells of `truth` into `known` and returns the
  /// indices of the cells revealed by this scan, in increasing offset-table order. The span
  /// stays valid until the next call. `rng` is used only when miss_probability > 0.
  std::span<const int> scan(const WorldMap& truth, KnownMap& known, Cell at, double heading_rad, Rng& rng);

  /// True when `target` is visible from `at` on `truth` under the range and line-of-sight rules
  /// (ignores field of view and noise). For tests and for information-gain estimates.
  [[nodiscard]] bool visible(const WorldMap& truth, Cell at, Cell target) const;

  [[nodiscard]] const SensorParams& params() const { return params_; }
  /// Sensing radius in cells.
  [[nodiscard]] double range_cells() const { return range_cells_; }

 private:
  SensorParams params_;
  double range_cells_ = 0.0;
  // Implementation tables (offsets, their crossed cells, corner pairs) are private details.
  struct Target {
    int dx = 0;
    int dy = 0;
    double angle = 0.0;
    std::uint32_t first = 0;   // into crossings_
    std::uint32_t count = 0;
  };
  struct Crossing {
    // A cell the ray enters (b_dx/b_dy unused, corner = false), or a corner touch whose two
    // side cells must not both be occupied (corner = true).
    int a_dx = 0, a_dy = 0, b_dx = 0, b_dy = 0;
    bool corner = false;
  };
  std::vector<Target> targets_;
  std::vector<Crossing> crossings_;
  std::vector<int> revealed_;
};

}  // namespace fsweep
