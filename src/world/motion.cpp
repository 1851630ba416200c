#include "world/motion.hpp"

namespace fsweep {
inline namespace world {

MotionCost measure_path(std::span<const Cell> path, int start_heading, const EnergyModel& energy,
                        double resolution_m) {
  MotionCost cost;
  int heading = start_heading;
  // Steps counted, the length computed once from the counts: exact (a + b sqrt(2) with one
  // rounding), so paths of equal length measure equal whatever their order of steps. A path is
  // mostly runs of one step: a step equal to the one before changes no heading and is only
  // counted, so the heading is worked out once per run rather than once per cell.
  long straight = 0;
  long diagonal = 0;
  Cell step{0, 0};  // never a step of a path from start_heading: the first one is worked out
  long* counter = &straight;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Cell d{path[i].x - path[i - 1].x, path[i].y - path[i - 1].y};
    if (d != step || i == 1) {
      step = d;
      const int h = heading_of(d.x, d.y);
      const int change = heading_difference(h, heading);
      if (change != 0) {
        ++cost.stops;
        ++cost.turns;
        cost.turned_deg += 45.0 * change;
        cost.energy += energy.turn(change);
      }
      counter = (h & 1) != 0 ? &diagonal : &straight;
      heading = h;
    }
    ++*counter;
  }
  const double cells = static_cast<double>(straight) + static_cast<double>(diagonal) * kSqrt2;
  cost.length_m = cells * resolution_m;
  cost.energy += energy.travel(cells, resolution_m);
  cost.final_heading = heading;
  return cost;
}

}  // namespace world
}  // namespace fsweep
