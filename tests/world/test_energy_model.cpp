#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

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
