#pragma once
/// @file reveal_bound.hpp
/// How far a run must still travel to reveal a number of cells, at least: the look-ahead half
/// of the coverage target's bound (Simulation::coverage_target_bound_m), which the exact weight
/// search prunes by. It counts what the battery costs: every trip to the far cells starts and
/// ends at the dock.
///
/// The argument, for a robot whose sensor sees a cell when their centres are at most r apart:
/// - Every cell a later scan reveals has its square within R = r + res / sqrt(2) of the path the
///   robot travels from now on, and a stretch of path of length d passes within R of at most
///   pi R^2 + 2 R d of area (the tube argument).
/// - Let g(c) be the path length from the dock to cell c on the true map and h(x) the least g(s)
///   over the cells s the robot can stand on whose sensor disc holds x: x is revealed only from a
///   cell at least h(x) from the dock. Of the cells still needed, all but the unknown ones with
///   h < rho have h >= rho, for any rho.
/// - The battery splits the rest of a run at its recharges into legs that start and end at the
///   dock (each at most a full charge long), the first from where the robot stands (at most what
///   the battery holds now) and the last ending where the run ends. A leg reveals cells with
///   h >= rho only between first reaching g >= rho and last leaving it, which leaves out at least
///   2 rho of a leg from the dock to the dock, rho of the last, rho - g(robot) (if positive) plus
///   rho of the first when it returns; a leg that never reaches rho reveals none of them (the
///   first one still travels g(robot) back to the dock).
/// - So with k full legs, travel T >= (overheads) + (M - n pi R^2) / (2 R) for the far area M
///   and n legs that reach rho, where the legs' lengths must hold M; for rho >= pi R / 4 another
///   leg never shortens T, so the fewest legs that hold M give the bound.
/// The largest of these bounds over rho (in steps of RevealGeometry::bin_m) and of the tube alone
/// (rho = 0) is the bound.

#include <cstdint>
#include <span>
#include <vector>

#include "sim/battery.hpp"
#include "world/energy_model.hpp"
#include "world/grid.hpp"

namespace fsweep {
inline namespace sim {

struct RunSetup;

/// The parts of the bound that depend only on the true map, the dock and the sensor (shared by
/// a run and its forks through RunSetup::reveal).
struct RevealGeometry {
  /// Width (metres) of a bin of reveal distances h: four cells.
  double bin_m = 1.0;
  /// Per cell: g, the path length (metres) from the dock on the true map (the run's corner
  /// rule); +infinity where the dock does not reach.
  std::vector<double> dock_m;
  /// Per reachable cell (RunSetup::reachable) that a cell the dock reaches sees: floor(h /
  /// bin_m); -1 elsewhere (every cell when the dock is not reachable from the start).
  std::vector<std::int32_t> bin;
  /// Bins in use (the largest bin + 1); 0 when the dock reaches no reachable cell.
  int bins = 0;
  /// R = r + res / sqrt(2) (metres), r the farthest a cell in the sensor's range can be
  /// (disc_extent(), sensor.hpp).
  double reach_m = 0.0;
};

/// The geometry of `setup`'s true map for a robot docked at `dock` (O(cells x sensor disc)).
[[nodiscard]] RevealGeometry reveal_geometry(const RunSetup& setup, Cell dock);

/// What travel_to_reveal_m() needs of a run's state.
struct RevealState {
  /// More reachable cells the run must reveal (may be fractional; <= 0: none).
  double needed_cells = 0.0;
  double cell_area_m2 = 1.0;
  /// R = r + res / sqrt(2) (metres).
  double reach_m = 1.0;
  /// g of the robot's cell (metres; +infinity when the dock is not reachable from it).
  double dock_m = 0.0;
  /// Metres the battery allows before the next recharge, and on a full charge (+infinity:
  /// unlimited).
  double first_charge_m = 0.0;
  double charge_m = 0.0;
  /// Bin width of `unknown_by_bin` (RevealGeometry::bin_m).
  double bin_m = 1.0;
};

/// Metres of travel a battery allows: before its next recharge (`first`) and on a full charge
/// (`full`); +infinity when unlimited, or when a cell's step costs no more than the overrun
/// Battery::draw allows (then an empty battery still moves).
struct Charges {
  double first = 0.0;
  double full = 0.0;
};
[[nodiscard]] Charges charges_m(const Battery& battery, const EnergyModel& energy, double resolution_m);

/// A lower bound on the travel (metres) that reveals `state.needed_cells` more cells, given the
/// unknown reachable cells per bin of h (`unknown_by_bin`; empty: the tube bound alone).
[[nodiscard]] double travel_to_reveal_m(const RevealState& state, std::span<const int> unknown_by_bin);

}  // namespace sim
}  // namespace fsweep
