#pragma once
/// @file scan_counts.hpp
/// What a simulated scan would see, counted by the cells' state on the known map (Sensor::gain).

namespace fsweep {
inline namespace world {

/// Cells a scan would see, by their state on the known map (see Sensor::gain).
struct ScanCounts {
  /// Visible cells that are still unknown: the cells the scan could reveal.
  int unknown = 0;
  /// Visible cells that are already known (free or occupied), the robot's own cell included.
  int known = 0;
  friend bool operator==(const ScanCounts&, const ScanCounts&) = default;
};

}  // namespace world
}  // namespace fsweep
