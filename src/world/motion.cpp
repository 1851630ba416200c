#include "world/motion.hpp"

namespace fsweep {
inline namespace world {

MotionCost measure_path(std::span<const Cell> path, int start_heading, const EnergyModel& energy,
                        double resolution_m) {
  MotionCost cost;
  int heading = start_heading;
  // Steps counted, the length computed once from the counts: exact (a + b sqrt(2) with one
  // rounding), so paths of equal length measure equal whatever their order of steps.
  long straight = 0;
  long diagonal = 0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const int h = heading_of(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y);
    const int change = heading_difference(h, heading);
    if (change != 0) {
      ++cost.stops;
      ++cost.turns;
      cost.turned_deg += 45.0 * change;
      cost.energy += energy.turn(change);
    }
    ++((h & 1) != 0 ? diagonal : straight);
    heading = h;
  }
  const double cells = static_cast<double>(straight) + static_cast<double>(diagonal) * kSqrt2;
  cost.length_m = cells * resolution_m;
  cost.energy += energy.travel(cells, resolution_m);
  cost.final_heading = heading;
  return cost;
}

}  // namespace world
}  // namespace fsweep
