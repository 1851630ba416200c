#include "world/motion.hpp"

namespace fsweep {
inline namespace world {
namespace {

/// The motion totals of a path fed in order as runs of equal steps. A step equal to the one
/// before changes no heading, so a run is worked out once, however many cells it has, and a
/// path measures the same however its runs are cut. Steps are counted and the length computed
/// once from the counts: exact (a + b sqrt(2) with one rounding), so paths of equal length
/// measure equal whatever their order of steps.
class MotionTally {
 public:
  MotionTally(int start_heading, const EnergyModel& energy) : energy_(energy), heading_(start_heading) {}

  /// `steps` more steps of `step` (a step that is not to an 8-neighbour has heading -1).
  void add_run(Cell step, long steps) {
    const int h = heading_of(step.x, step.y);
    const int change = heading_difference(h, heading_);
    if (change != 0) {
      ++cost_.stops;
      ++cost_.turns;
      cost_.turned_deg += 45.0 * change;
      cost_.energy += energy_.turn(change);
    }
    ((h & 1) != 0 ? diagonal_ : straight_) += steps;
    heading_ = h;
  }

  [[nodiscard]] MotionCost finish(double resolution_m) const {
    MotionCost cost = cost_;
    const double cells = static_cast<double>(straight_) + static_cast<double>(diagonal_) * kSqrt2;
    cost.length_m = cells * resolution_m;
    cost.energy += energy_.travel(cells, resolution_m);
    cost.final_heading = heading_;
    return cost;
  }

 private:
  const EnergyModel& energy_;
  MotionCost cost_;
  int heading_;
  long straight_ = 0;
  long diagonal_ = 0;
};

}  // namespace

MotionCost measure_path(std::span<const Cell> path, int start_heading, const EnergyModel& energy,
                        double resolution_m) {
  MotionTally tally(start_heading, energy);
  const auto step = [&](std::size_t i) { return Cell{path[i].x - path[i - 1].x, path[i].y - path[i - 1].y}; };
  for (std::size_t i = 1; i < path.size();) {
    const Cell d = step(i);
    std::size_t end = i + 1;
    while (end < path.size() && step(end) == d) ++end;
    tally.add_run(d, static_cast<long>(end - i));
    i = end;
  }
  return tally.finish(resolution_m);
}

MotionCost measure_jump_points(std::span<const Cell> jump_points, int start_heading,
                               const EnergyModel& energy, double resolution_m) {
  MotionTally tally(start_heading, energy);
  for_each_jump_run(jump_points, [&tally](Cell step, int steps) { tally.add_run(step, steps); });
  return tally.finish(resolution_m);
}

}  // namespace world
}  // namespace fsweep
