// The look-ahead bound of the coverage target (sim/reveal_bound.hpp) on states worked out by
// hand: the legs between recharges, the way out to the far cells and back, and the geometry it
// reads off a map.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <vector>

#include "sim/reveal_bound.hpp"
#include "sim/run_setup.hpp"
#include "strategies/registry.hpp"
#include "world/energy_model.hpp"
#include "world/map_spec.hpp"

namespace fsweep {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kUnlimited = std::numeric_limits<double>::infinity();

// R = 1 (a disc of pi, a tube 2 wide), cells of 1 m^2, bins 10 m wide; all 100 cells still needed
// lie at h in [10, 20) from the dock, so rho = 10 m is the only cut that sees them as far.
RevealState far_cells_state() {
  RevealState s;
  s.needed_cells = 100.0;
  s.cell_area_m2 = 1.0;
  s.reach_m = 1.0;
  s.bin_m = 10.0;
  return s;
}
const std::vector<int> kFarCells{0, 150};

TEST(RevealBound, WithoutABatteryItIsTheWayOutPlusTheTube) {
  RevealState s = far_cells_state();
  s.first_charge_m = s.charge_m = kUnlimited;
  s.dock_m = 0.0;
  EXPECT_DOUBLE_EQ(travel_to_reveal_m(s, kFarCells), 10.0 + (100.0 - kPi) / 2.0);
  // From 4 m out, 6 m are left to go; from beyond rho, none.
  s.dock_m = 4.0;
  EXPECT_DOUBLE_EQ(travel_to_reveal_m(s, kFarCells), 6.0 + (100.0 - kPi) / 2.0);
  s.dock_m = 15.0;
  EXPECT_DOUBLE_EQ(travel_to_reveal_m(s, kFarCells), (100.0 - kPi) / 2.0);
  // No bins: the tube alone.
  EXPECT_DOUBLE_EQ(travel_to_reveal_m(s, {}), (100.0 - kPi) / 2.0);
}

TEST(RevealBound, CountsTheLegsEachChargeAllows) {
  // A charge of 30 m from the dock, full: a leg from the dock to the dock leaves 30 - 2 x 10 m
  // out there (a far area of 20 + pi), the last leg 30 - 10 m (40 + pi), and the first, from the
  // dock, is such a leg too. The far area of 100 needs the first and the last leg and
  // ceil((100 - (20 + pi) - (40 + pi)) / (20 + pi)) = 2 full legs (or, with a first leg that
  // stays near, 3): 20 + 10 + 2 x 20 m of ways out and back plus (100 - 4 pi) / 2 m out there.
  RevealState s = far_cells_state();
  s.first_charge_m = s.charge_m = 30.0;
  s.dock_m = 0.0;
  EXPECT_DOUBLE_EQ(travel_to_reveal_m(s, kFarCells), 70.0 + (100.0 - 4.0 * kPi) / 2.0);
  // Half the cells nearer than rho: the 50 far ones fit into the first leg and the last (or the
  // last and one full leg): 30 m of ways out and back plus (50 - 2 pi) / 2 m out there, more than
  // the tube alone ((100 - pi) / 2).
  EXPECT_DOUBLE_EQ(travel_to_reveal_m(s, std::vector<int>{50, 150}), 30.0 + (50.0 - 2.0 * kPi) / 2.0);
  // A charge too short to come back from rho (20 m): only the last leg may go that far.
  s.first_charge_m = s.charge_m = 19.0;
  EXPECT_DOUBLE_EQ(travel_to_reveal_m(s, kFarCells), (100.0 - kPi) / 2.0);
}

TEST(RevealBound, ARobotThatCannotReachTheDockEndsWithinItsCharge) {
  RevealState s = far_cells_state();
  s.charge_m = 30.0;
  s.dock_m = 12.0;
  // 60 m of charge left but 100 m^2 far away: one leg of at most 60 m holds 2 x 60 + pi, enough.
  s.first_charge_m = 60.0;
  EXPECT_DOUBLE_EQ(travel_to_reveal_m(s, kFarCells), (100.0 - kPi) / 2.0);
  // 11 m left, 12 m from the dock: no recharge ahead, and 2 x 11 + pi does not hold 100 m^2:
  // no way to reveal them, and the bound falls back to the tube.
  s.first_charge_m = 11.0;
  EXPECT_DOUBLE_EQ(travel_to_reveal_m(s, kFarCells), (100.0 - kPi) / 2.0);
}

TEST(RevealBound, ChargesAreTheMetresTheBatteryPaysFor) {
  // distance: 1 per metre; mei2006: 1 per cell length, so 0.5 per metre with 2 m cells.
  const EnergyModel distance = energy_preset("distance");
  Battery battery(1200.0, 1.0);
  Charges c = charges_m(battery, distance, 5.0);
  EXPECT_NEAR(c.first, 1200.0, 1e-5);
  EXPECT_GE(c.first, 1200.0) << "the draw's overrun counts";
  EXPECT_EQ(c.first, c.full);
  ASSERT_TRUE(battery.draw(300.0, 300.0));
  c = charges_m(battery, energy_preset("mei2006"), 2.0);
  EXPECT_NEAR(c.first, 1800.0, 1e-5);
  EXPECT_NEAR(c.full, 2400.0, 1e-5);
  // Unlimited, and a step that costs no more than the overrun a draw may take: no bound.
  c = charges_m(Battery(kUnlimited, 1.0), distance, 5.0);
  EXPECT_EQ(c.first, kUnlimited);
  EXPECT_EQ(c.full, kUnlimited);
  c = charges_m(Battery(1e10, 1.0), distance, 5.0);
  EXPECT_EQ(c.first, kUnlimited);
}

TEST(RevealBound, NothingNeededCostsNothing) {
  RevealState s = far_cells_state();
  s.needed_cells = 0.0;
  EXPECT_EQ(travel_to_reveal_m(s, kFarCells), 0.0);
  s.needed_cells = -3.0;
  EXPECT_EQ(travel_to_reveal_m(s, kFarCells), 0.0);
}

TEST(RevealBound, GeometryBinsEachCellByTheNearestPlaceThatSeesIt) {
  // A corridor 1 cell high and 30 long inside a wall (x = 1..30, y = 1), the dock at its west
  // end, 1 m cells, a sensor of 3 m: cell x is first seen from x - 3, so h(x) = max(0, x - 4) m,
  // in bins of 4 m.
  RunSpec spec;
  spec.map = std::make_shared<const WorldMap>(load_map_spec("free:w=32,h=3"));
  spec.strategy = configure_strategy("closest_frontier", nullptr);
  spec.robot.sensor.range_m = 3.0;
  const RunSetup setup(spec);
  const RevealGeometry g = reveal_geometry(setup, Cell{1, 1});
  ASSERT_EQ(g.bin.size(), 32U * 3U);
  EXPECT_EQ(g.bin_m, 4.0);
  for (int x = 0; x < 32; ++x) {
    const auto at = static_cast<std::size_t>(32 + x);
    if (x == 0 || x == 31) {  // the wall: not reachable
      EXPECT_EQ(g.bin[at], -1) << x;
      continue;
    }
    EXPECT_EQ(g.dock_m[at], x - 1) << x;
    EXPECT_EQ(g.bin[at], std::max(0, x - 4) / 4) << x;
    EXPECT_EQ(g.bin[static_cast<std::size_t>(x)], -1) << "the wall above " << x;
  }
  EXPECT_EQ(g.bins, 7);  // h up to 26 m
}

TEST(RevealBound, GeometryEqualsTheDefinitionOnRooms) {
  // h(x) = min g(s) over the reachable cells s within the sensor's range of x, by brute force.
  for (const double range_m : {1.5, 3.0, 4.2}) {
    RunSpec spec;
    spec.map = std::make_shared<const WorldMap>(load_map_spec("rooms:w=40,h=30,door=2,seed=4"));
    spec.strategy = configure_strategy("closest_frontier", nullptr);
    spec.robot.sensor.range_m = range_m;
    const RunSetup setup(spec);
    const Cell dock = setup.map().start;
    const RevealGeometry g = reveal_geometry(setup, dock);
    const double cells = range_m / setup.resolution_m;
    int checked = 0;
    for (int i = 0; i < setup.reachable.size(); ++i) {
      if (setup.reachable[i] == 0) {
        EXPECT_EQ(g.bin[static_cast<std::size_t>(i)], -1);
        continue;
      }
      const Cell x = setup.reachable.cell(i);
      double h = std::numeric_limits<double>::infinity();
      for (int j = 0; j < setup.reachable.size(); ++j) {
        const Cell c = setup.reachable.cell(j);
        const double d2 = static_cast<double>((c.x - x.x) * (c.x - x.x) + (c.y - x.y) * (c.y - x.y));
        if (setup.reachable[j] != 0 && d2 <= cells * cells)
          h = std::min(h, g.dock_m[static_cast<std::size_t>(j)]);
      }
      ASSERT_TRUE(std::isfinite(h));
      EXPECT_EQ(g.bin[static_cast<std::size_t>(i)], static_cast<int>(std::floor(h / g.bin_m)))
          << range_m << " " << i;
      ++checked;
    }
    EXPECT_GT(checked, 500);
  }
}

}  // namespace
}  // namespace fsweep
