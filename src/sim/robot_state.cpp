#include "sim/robot_state.hpp"

#include "core/config_error.hpp"

namespace fsweep {
inline namespace sim {

RobotState::RobotState(const RunSetup& setup)
    : position(setup.map().start),
      heading(setup.spec.robot.start_heading),
      dock(setup.spec.robot.dock.value_or(setup.map().start)),
      previous_position(setup.map().start) {
  const WorldMap& truth = setup.map();
  if (!truth.is_free(dock)) {
    throw ConfigError("robot/dock", "dock cell " + cell_text(dock) + " is outside the map or occupied in " +
                                        truth.source + "; allowed: a free cell");
  }
  const EnergyModel& e = setup.spec.robot.energy;
  battery = Battery(setup.spec.robot.battery_capacity, e.per_metre + e.per_cell / setup.resolution_m);
}

StepCost RobotState::step_cost(Cell next, const RunSetup& setup) const {
  StepCost c;
  c.heading = heading_of(next.x - position.x, next.y - position.y);
  c.turns = heading_difference(c.heading, heading);
  const EnergyModel& e = setup.spec.robot.energy;
  const double cells = step_length(c.heading);
  c.energy = e.turn(c.turns) + e.travel(cells, setup.resolution_m);
  c.metres = cells * setup.resolution_m;
  return c;
}

}  // namespace sim
}  // namespace fsweep
