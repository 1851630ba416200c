#pragma once
/// @file robot_state.hpp
/// The robot part of a Simulation: where it is, where it heads, its battery and dock, what it did
/// at the previous decision. A plain value (copied when a run is forked).

#include <optional>

#include "sim/battery.hpp"
#include "sim/run_setup.hpp"
#include "strategies/strategy.hpp"
#include "world/grid.hpp"

namespace fsweep {
inline namespace sim {

/// The cost of one cell step (docs/dev/architecture.md, "Robot, motion and energy").
struct StepCost {
  /// Heading of the step (0..7) and the 45-degree turns from the previous heading (0..4).
  int heading = 0;
  int turns = 0;
  /// Length (metres) and energy (the energy model's unit) of the step, the turn included.
  double metres = 0.0;
  double energy = 0.0;
};

struct RobotState {
  RobotState() = default;
  /// At the map's start with the spec's heading and a full battery. Throws ConfigError
  /// ("robot/dock") when the dock (RobotParams::dock, default the start) is not a free cell.
  explicit RobotState(const RunSetup& setup);

  /// What a step from `position` to the 8-neighbour `next` costs.
  [[nodiscard]] StepCost step_cost(Cell next, const RunSetup& setup) const;
  /// The battery as strategies see it.
  [[nodiscard]] BatteryView battery_view() const {
    return BatteryView{battery.level(), battery.capacity(), battery.remaining_range_m()};
  }

  Cell position{};
  /// 0..7 (grid.hpp).
  int heading = 0;
  Cell dock{};
  Battery battery{0.0, 1.0};
  /// Where the robot was at the previous decision that moved it on (the start before that),
  /// and that decision's goal.
  Cell previous_position{};
  std::optional<Cell> previous_goal;
  /// Decisions in a row that revealed nothing (the `stuck` rule, SimParams::stuck_decisions).
  int quiet_decisions = 0;
};

}  // namespace sim
}  // namespace fsweep
