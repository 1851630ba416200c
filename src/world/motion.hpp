#pragma once
/// @file motion.hpp
/// Measuring an 8-connected cell path: length, energy, stops and turns, with one rule shared
/// by planners and the simulator (see energy_model.hpp).

#include <algorithm>
#include <cstddef>
#include <cstdlib>
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

/// The runs of equal steps that join a chain of jump points, in order: each consecutive pair by
/// a diagonal run and then a straight one, either of which may be empty (the pair on one line)
/// and is then skipped. Calls run(step, steps) with steps >= 1. The one rule by which JPS paths
/// are filled in (jump_points::fill_segments()) and measured (measure_jump_points()).
template <typename Run>
void for_each_jump_run(std::span<const Cell> jump_points, Run&& run) {
  for (std::size_t i = 1; i < jump_points.size(); ++i) {
    const int dx = jump_points[i].x - jump_points[i - 1].x;
    const int dy = jump_points[i].y - jump_points[i - 1].y;
    const int across = std::abs(dx);
    const int along = std::abs(dy);
    const int diagonal = std::min(across, along);
    const int straight = std::max(across, along) - diagonal;
    if (diagonal > 0) run(Cell{sign_of(dx), sign_of(dy)}, diagonal);
    if (straight > 0) run(across > along ? Cell{sign_of(dx), 0} : Cell{0, sign_of(dy)}, straight);
  }
}

/// measure_path() of the cells that join `jump_points` (for_each_jump_run()), worked out from the
/// jump points alone: the same totals, without walking the cells.
[[nodiscard]] MotionCost measure_jump_points(std::span<const Cell> jump_points, int start_heading,
                                             const EnergyModel& energy, double resolution_m);

}  // namespace world
}  // namespace fsweep
