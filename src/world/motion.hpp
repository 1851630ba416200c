#pragma once
/// @file motion.hpp
/// Measuring an 8-connected cell path: length, energy, stops and turns, with one rule shared
/// by planners and the simulator (see energy_model.hpp).

#include <span>
#include <vector>

#include "world/energy_model.hpp"
#include "world/grid.hpp"

namespace fsweep {
inline namespace world {

/// Motion totals of a path.
struct MotionCost {
  double length_m = 0.0;
  double energy = 0.0;
  int stops = 0;
  int turns = 0;
  /// Sum of absolute turn angles (degrees).
  double turned_deg = 0.0;
  /// Heading after the last step (the start heading for an empty path).
  int final_heading = 0;
};

/// Costs of following `path` (consecutive cells are 8-neighbours; path[0] is the start)
/// from `start_heading`. Every heading change is one stop plus one turn.
[[nodiscard]] MotionCost measure_path(std::span<const Cell> path, int start_heading,
                                      const EnergyModel& energy, double resolution_m);

/// measure_path() of the cells that join `jump_points`, each consecutive pair by a diagonal run
/// and then a straight one (as the planners' jump_points::fill_segments() fills a JPS path),
/// worked out from the jump points alone: the same totals, without walking the cells.
[[nodiscard]] MotionCost measure_jump_points(std::span<const Cell> jump_points, int start_heading,
                                             const EnergyModel& energy, double resolution_m);

}  // namespace world
}  // namespace fsweep
