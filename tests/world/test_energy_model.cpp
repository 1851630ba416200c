#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <random>

#include "core/config_error.hpp"
#include "world/energy_model.hpp"
#include "world/motion.hpp"

namespace fsweep {
namespace {

// An L-shaped path: 2 steps east, then 2 steps south, starting facing east.
const std::vector<Cell> kLPath{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}};

TEST(EnergyModel, DistancePresetCountsMetresOnly) {
  const MotionCost c = measure_path(kLPath, /*start_heading=*/0, energy_preset("distance"), 0.5);
  EXPECT_DOUBLE_EQ(c.length_m, 2.0);
  EXPECT_DOUBLE_EQ(c.energy, 2.0);
  EXPECT_EQ(c.stops, 1);
  EXPECT_EQ(c.turns, 1);
  EXPECT_DOUBLE_EQ(c.turned_deg, 90.0);
  EXPECT_EQ(c.final_heading, 2);
}

TEST(EnergyModel, Mei2006CountsCellsStopsAndTurns) {
  // Hand calculation: 4 cell lengths + one stop (0.5) + one 90-degree turn (0.6) = 5.1.
  const MotionCost c = measure_path(kLPath, 0, energy_preset("mei2006"), 0.5);
  EXPECT_DOUBLE_EQ(c.energy, 5.1);
}

TEST(EnergyModel, StartHeadingChangeIsAStopAndTurn) {
  // Facing west (4) and leaving east: a 180-degree turn, cost 0.5 + 1.0, plus 1 cell.
  const std::vector<Cell> path{{0, 0}, {1, 0}};
  const MotionCost c = measure_path(path, 4, energy_preset("mei2006"), 1.0);
  EXPECT_DOUBLE_EQ(c.energy, 2.5);
  EXPECT_EQ(c.stops, 1);
}

TEST(EnergyModel, DiagonalStepIsSqrt2) {
  const std::vector<Cell> path{{0, 0}, {1, 1}, {2, 2}};
  const MotionCost c = measure_path(path, 1, energy_preset("mei2006"), 1.0);
  EXPECT_DOUBLE_EQ(c.length_m, 2 * kSqrt2);
  EXPECT_DOUBLE_EQ(c.energy, 2 * kSqrt2);
  EXPECT_EQ(c.turns, 0);
}

/// measure_path() one cell at a time, as it is defined: every step's heading against the one
/// before, a stop and a turn wherever it changes.
MotionCost measure_each_step(const std::vector<Cell>& path, int heading, const EnergyModel& energy,
                             double resolution_m) {
  MotionCost cost;
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

/// Every total of `got` equals `want`'s, exactly.
void expect_same_motion(const MotionCost& got, const MotionCost& want, int trial) {
  EXPECT_EQ(got.length_m, want.length_m) << "trial " << trial;
  EXPECT_EQ(got.energy, want.energy) << "trial " << trial;
  EXPECT_EQ(got.stops, want.stops) << "trial " << trial;
  EXPECT_EQ(got.turns, want.turns) << "trial " << trial;
  EXPECT_EQ(got.turned_deg, want.turned_deg) << "trial " << trial;
  EXPECT_EQ(got.final_heading, want.final_heading) << "trial " << trial;
}

TEST(EnergyModel, MeasurePathEqualsMeasuringEachStep) {
  // Paths of runs of 1 to 5 equal steps in random headings (reversals and repeated headings
  // included), from every start heading, with turns that cost differently for each angle.
  EnergyModel energy = energy_preset("mei2006");
  energy.per_turn = {0.11, 0.23, 0.37, 0.41};
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Cell> path{{0, 0}};
    const int runs = static_cast<int>(rng() % 12);
    for (int r = 0; r < runs; ++r) {
      const Cell d = kDirections[rng() % 8];
      for (int k = 1 + static_cast<int>(rng() % 5); k > 0; --k) {
        path.push_back(Cell{path.back().x + d.x, path.back().y + d.y});
      }
    }
    const int start = trial % 8;
    const MotionCost got = measure_path(path, start, energy, 0.25);
    const MotionCost want = measure_each_step(path, start, energy, 0.25);
    expect_same_motion(got, want, trial);
  }
}

TEST(EnergyModel, MeasureJumpPointsEqualsMeasuringTheirCells) {
  // Chains of jump points at random offsets (straight, diagonal, both, repeated points), their
  // cells filled here by the rule (a diagonal run, then a straight one) and measured one by one.
  EnergyModel energy = energy_preset("mei2006");
  energy.per_turn = {0.11, 0.23, 0.37, 0.41};
  std::mt19937 rng(11);
  const auto offset = [&rng] { return static_cast<int>(rng() % 9) - 4; };
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<Cell> jump_points{{0, 0}};
    for (int k = static_cast<int>(rng() % 8); k > 0; --k) {
      const Cell last = jump_points.back();
      jump_points.push_back(trial % 5 == 0 ? last : Cell{last.x + offset(), last.y + offset()});
    }
    std::vector<Cell> cells{jump_points.front()};
    for (std::size_t i = 1; i < jump_points.size(); ++i) {
      Cell c = cells.back();
      const Cell to = jump_points[i];
      while (c.x != to.x && c.y != to.y)
        cells.push_back(c = Cell{c.x + sign_of(to.x - c.x), c.y + sign_of(to.y - c.y)});
      while (c != to) cells.push_back(c = Cell{c.x + sign_of(to.x - c.x), c.y + sign_of(to.y - c.y)});
    }
    const int start = trial % 8;
    const MotionCost got = measure_jump_points(jump_points, start, energy, 0.5);
    const MotionCost want = measure_each_step(cells, start, energy, 0.5);
    expect_same_motion(got, want, trial);
  }
}

TEST(EnergyModel, Pioneer3dxUsesRappaportPowers) {
  const EnergyModel m = energy_preset("pioneer3dx");
  // 22.38 W at 1.2 m/s for one metre = 18.65 J = 18.65 / 3600 Wh.
  EXPECT_NEAR(m.per_metre, 22.38 / 1.2 / 3600.0, 1e-15);
  // A stop stands 1 s at 13.5 W.
  EXPECT_NEAR(m.per_stop, 13.5 / 3600.0, 1e-15);
  // A 90-degree turn at 90 deg/s draws the moving power for 1 s.
  EXPECT_NEAR(m.per_turn[1], 22.38 / 3600.0, 1e-15);
  EXPECT_EQ(m.unit, "Wh");
}

TEST(EnergyModel, JsonOverridesPreset) {
  const auto j = nlohmann::json::parse(R"({"preset": "mei2006", "per_stop": 0.7})");
  const EnergyModel m = energy_model_from_json(j, "/robot/energy");
  EXPECT_DOUBLE_EQ(m.per_stop, 0.7);
  EXPECT_DOUBLE_EQ(m.per_turn[1], 0.6);
}

TEST(EnergyModel, JsonPerTurnTakesFourNumbers) {
  const auto j = nlohmann::json::parse(R"({"preset": "mei2006", "per_stop": 0, "per_turn": [0, 0.1, 0, 0]})");
  const EnergyModel m = energy_model_from_json(j, "/robot/energy");
  EXPECT_DOUBLE_EQ(m.per_turn[1], 0.1);
  EXPECT_DOUBLE_EQ(m.per_stop, 0.0);
  try {
    (void)energy_model_from_json(nlohmann::json::parse(R"({"per_turn": [0, -1, 0, 0]})"), "/e");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("/e/per_turn"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)energy_model_from_json(nlohmann::json::parse(R"({"per_turn": [0, 0]})"), "/e"),
               ConfigError);
}

TEST(EnergyModel, BadJsonNamesPathAndAllowed) {
  try {
    (void)energy_model_from_json(nlohmann::json::parse(R"({"preset": "tesla"})"), "/robot/energy");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("/robot/energy/preset"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("distance, mei2006, pioneer3dx"), std::string::npos);
  }
  EXPECT_THROW((void)energy_model_from_json(nlohmann::json::parse(R"({"per_stop": -1})"), "/e"), ConfigError);
  EXPECT_THROW((void)energy_model_from_json(nlohmann::json::parse(R"({"watts": 3})"), "/e"), ConfigError);
}

}  // namespace
}  // namespace fsweep
