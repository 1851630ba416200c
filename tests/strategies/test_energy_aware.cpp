// Hand-worked situations for Rappaport 2016's energy-aware strategy (section 3.2, Algorithm 1).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>

#include "core/config_error.hpp"
#include "core/random.hpp"
#include "search/distance_field.hpp"
#include "strategies/energy_aware.hpp"
#include "strategies/registry.hpp"
#include "world/ascii_world.hpp"

namespace fsweep {
namespace {

/// Answers distance queries from fixed tables and records the bounds it was asked with.
class TableOracle final : public DistanceOracle {
 public:
  std::map<int, double> robot, dock;
  double last_robot_bound = -1, last_dock_bound = -1;
  std::vector<double> from_robot(std::span<const int> cells, double bound_m) override {
    last_robot_bound = bound_m;
    return read(robot, cells, bound_m);
  }
  std::vector<double> from_dock(std::span<const int> cells, double bound_m) override {
    last_dock_bound = bound_m;
    return read(dock, cells, bound_m);
  }
  int nearest_from_robot(std::span<const int> cells) override {
    int best = -1;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (best < 0 || robot.at(cells[i]) < robot.at(cells[static_cast<std::size_t>(best)]))
        best = static_cast<int>(i);
    }
    return best;
  }

 private:
  static std::vector<double> read(const std::map<int, double>& t, std::span<const int> cells, double bound) {
    std::vector<double> out;
    for (const int c : cells) {
      const double d = t.at(c);
      out.push_back(d <= bound ? d : std::numeric_limits<double>::infinity());
    }
    return out;
  }
};

// The situation: 11x11 map, robot at (5,5) having come from (2,5) (heading east), dock at (5,9).
// Three frontier clusters: A east at (9,5), B north at (5,1), C west at (1,5).
struct Situation {
  KnownMap known;
  FrontierMap frontiers{known};
  std::vector<FrontierCluster> clusters;
  TableOracle oracle;
  SensorParams sensor;
  Cell robot{5, 5}, previous{2, 5}, dock{5, 9};
  Cell a{9, 5}, b{5, 1}, c{1, 5};

  explicit Situation(double resolution_m = 1.0) : known(11, 11, resolution_m) {
    for (const Cell f : {a, b, c}) {
      FrontierCluster cl;
      cl.representative = known.index(f);
      cl.cells = {cl.representative};
      clusters.push_back(cl);
    }
  }
  Observation observe(BatteryView battery) {
    return Observation{known, frontiers, clusters,     oracle, sensor,  robot,
                       0,     previous,  std::nullopt, dock,   battery, 1};
  }
};

EnergyAware make(double w1, double w2, double w3, double w4, const std::string& distance = "euclidean") {
  EnergyAwareParams p;
  p.w1 = w1;
  p.w2 = w2;
  p.w3 = w3;
  p.w4 = w4;
  p.distance = distance;
  return EnergyAware("energy_aware", p);
}

TEST(EnergyAware, FeaturesMatchHandComputation) {
  Situation s;
  // Capacity 20, level 12 (> half): d_gbe = -d_gb. Remaining range 30: everything in reach.
  auto ea = make(1, 0, 0, 0);
  const Candidates c = ea.candidates(s.observe({12.0, 20.0, 30.0}));
  ASSERT_EQ(c.cells.size(), 3U);
  const double r32 = std::sqrt(32.0);
  // A: d_g 4, d_gb |(9,5)-(5,9)| = sqrt(32), theta_rel 0 (straight ahead).
  EXPECT_DOUBLE_EQ(c.features[0], 4.0);
  EXPECT_DOUBLE_EQ(c.features[1], r32);
  EXPECT_DOUBLE_EQ(c.features[2], -r32);
  EXPECT_DOUBLE_EQ(c.features[3], 0.0);
  // B: d_g 4, d_gb 8, theta_rel 0.5 (a quarter turn).
  EXPECT_DOUBLE_EQ(c.features[4], 4.0);
  EXPECT_DOUBLE_EQ(c.features[5], 8.0);
  EXPECT_DOUBLE_EQ(c.features[6], -8.0);
  EXPECT_DOUBLE_EQ(c.features[7], 0.5);
  // C: behind the robot: theta_rel 1.
  EXPECT_DOUBLE_EQ(c.features[11], 1.0);
}

TEST(EnergyAware, DistancesInCellsAreMetresOverTheResolution) {
  // 10 m cells, capacity 20, level 12 (above half: d_gbe = -d_gb), 300 m left: all in reach.
  Situation s(10.0);
  const BatteryView full{12.0, 20.0, 300.0};
  EnergyAwareParams p;
  p.w1 = 0;
  p.w2 = 0;
  p.w3 = 1;
  p.w4 = 30;
  p.distance = "euclidean";
  EnergyAware metres("energy_aware", p);
  p.unit = "cell";
  EnergyAware cells("energy_aware", p);
  const Candidates c = cells.candidates(s.observe(full));
  ASSERT_EQ(c.cells.size(), 3U);
  // A: d_g 4 cells (40 m), d_gb sqrt(32) cells, theta_rel 0; B: d_gb 8 cells, theta_rel 0.5.
  EXPECT_DOUBLE_EQ(c.features[0], 4.0);
  EXPECT_DOUBLE_EQ(c.features[1], std::sqrt(32.0));
  EXPECT_DOUBLE_EQ(c.features[2], -std::sqrt(32.0));
  EXPECT_DOUBLE_EQ(c.features[3], 0.0);
  EXPECT_DOUBLE_EQ(c.features[6], -8.0);
  EXPECT_DOUBLE_EQ(c.features[7], 0.5);
  EXPECT_DOUBLE_EQ(metres.candidates(s.observe(full)).features[6], -80.0);
  // w3 d_gbe + w4 theta_rel: in metres B wins (-80 + 15 < -56.6 + 0), in cells A
  // (-5.66 + 0 < -8 + 15): the unit decides how much the turn weighs.
  EXPECT_EQ(metres.decide(s.observe(full)).goal, s.b);
  EXPECT_EQ(cells.decide(s.observe(full)).goal, s.a);
  // Recorded only when set: runs that do not set it keep their run keys.
  EXPECT_FALSE(energy_aware_params().write(EnergyAwareParams{}).contains("unit"));
  EXPECT_EQ(energy_aware_params().write(p)["unit"], "cell");
}

TEST(EnergyAware, EachTermDrivesTheChoice) {
  Situation s;
  const BatteryView full{12.0, 20.0, 30.0};
  // Orientation only: straight ahead (A).
  EXPECT_EQ(make(0, 0, 0, 1).decide(s.observe(full)).goal, s.a);
  // d_gbe above half charge: farthest from the dock (B, d_gb = 8).
  EXPECT_EQ(make(0, 0, 1, 0).decide(s.observe(full)).goal, s.b);
  // d_gb: closest to the dock; A and C tie at sqrt(32): the lowest cluster index (A) wins.
  EXPECT_EQ(make(0, 1, 0, 0).decide(s.observe(full)).goal, s.a);
  // Below half charge d_gbe flips to +d_gb (eq. 9): closest to the dock again.
  EXPECT_EQ(make(0, 0, 1, 0).decide(s.observe({9.0, 20.0, 30.0})).goal, s.a);
}

TEST(EnergyAware, ReachFilterIsStrict) {
  Situation s;
  // d_l = 12: B needs d_g + d_gb = 4 + 8 = 12, which is not < 12 (eq. 7): filtered out.
  auto ea = make(0, 0, 1, 0);
  const Candidates c = ea.candidates(s.observe({12.0, 20.0, 12.0}));
  ASSERT_EQ(c.cells.size(), 2U);
  EXPECT_EQ(c.cells[0], s.a);
  EXPECT_EQ(c.cells[1], s.c);
}

TEST(EnergyAware, ReturnsToDockWhenNothingInReachAndFinishesAtDock) {
  Situation s;
  auto ea = make(10, 0, 9, 20);
  EXPECT_EQ(ea.decide(s.observe({3.0, 20.0, 5.0})).kind, Decision::Kind::ReturnToDock);
  s.robot = s.dock;
  EXPECT_EQ(ea.decide(s.observe({20.0, 20.0, 5.0})).kind, Decision::Kind::Finish);
}

TEST(EnergyAware, PathDistancesComeFromTheOracleBoundedByRange) {
  Situation s;
  s.oracle.robot = {{s.known.index(s.a), 7.0}, {s.known.index(s.b), 2.0}, {s.known.index(s.c), 9.0}};
  s.oracle.dock = {{s.known.index(s.a), 3.0}, {s.known.index(s.b), 3.0}, {s.known.index(s.c), 3.0}};
  auto ea = make(1, 0, 0, 0, "path");
  EXPECT_EQ(ea.decide(s.observe({12.0, 20.0, 11.0})).goal, s.b);
  EXPECT_DOUBLE_EQ(s.oracle.last_robot_bound, 11.0);
  EXPECT_DOUBLE_EQ(s.oracle.last_dock_bound, 11.0);
  // C is 9 + 3 = 12 > 11 away: filtered; with range 10 only B (5) remains in reach.
  const Candidates c = ea.candidates(s.observe({12.0, 20.0, 10.0}));
  ASSERT_EQ(c.cells.size(), 1U);
  EXPECT_EQ(c.cells[0], s.b);
}

TEST(EnergyAware, FirstDecisionUsesAtan2OfZeroAsAlgorithm1) {
  Situation s;
  s.previous = s.robot;  // no motion yet: theta_r = atan2(0, 0) = 0, i.e. "facing" +x
  auto ea = make(0, 0, 0, 1);
  EXPECT_EQ(ea.decide(s.observe({20.0, 20.0, 100.0})).goal, s.a);
}

TEST(ClosestFrontier, IsEnergyAwareWithWeights1000) {
  auto cf = make_strategy("closest_frontier", nullptr, 0);
  auto* linear = dynamic_cast<LinearScoredStrategy*>(cf.get());
  ASSERT_NE(linear, nullptr);
  const auto w = linear->weights();
  EXPECT_EQ(std::vector<double>(w.begin(), w.end()), (std::vector<double>{1, 0, 0, 0}));
}

TEST(EnergyAware, ParamsValidateEveryProblemWithPath) {
  const auto j = nlohmann::json::parse(R"({"w1": 300, "w4": -1, "distance": "manhattan"})");
  try {
    (void)energy_aware_params().read(j, "/strategies/0/params");
    FAIL();
  } catch (const ConfigError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("/strategies/0/params/w1"), std::string::npos) << m;
    EXPECT_NE(m.find("/strategies/0/params/w4"), std::string::npos) << m;
    EXPECT_NE(m.find("[0, 250]"), std::string::npos) << m;
    EXPECT_NE(m.find("\"euclidean\""), std::string::npos) << m;
  }
  EXPECT_THROW((void)make_strategy("energy_aware", nlohmann::json{{"w5", 1}}, 0), ConfigError);
  try {
    (void)make_strategy("nearest", nullptr, 0);
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("closest_frontier, energy_aware"), std::string::npos);
  }
}

TEST(EnergyAware, OctilePathKnownFreeOnlyWhereTheOctileLengthIsTheSearchedLength) {
  // Where octile_path_known_free() holds, decide() takes the octile length for d_g without a
  // search: on seeded random maps (known free, occupied and unknown cells) it must equal the
  // searched length bit for bit under both corner rules. It must hold often, and never in a
  // case where the searched length is longer.
  Rng rng = make_rng(11, "octile-path-test");
  int held = 0;
  int longer = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int width = 2 + static_cast<int>(uniform_below(rng, 20));
    const int height = 2 + static_cast<int>(uniform_below(rng, 20));
    const double occupied = 0.3 * uniform01(rng);
    const double unknown = 0.2 * uniform01(rng);
    const KnownMap known =
        test::random_partly_known(width, height, 1.0 - unknown - occupied, occupied, rng, 0.5);
    const auto cell = [&] {
      return Cell{static_cast<int>(uniform_below(rng, static_cast<std::uint64_t>(width))),
                  static_cast<int>(uniform_below(rng, static_cast<std::uint64_t>(height)))};
    };
    for (int pair = 0; pair < 10; ++pair) {
      const Cell from = cell();
      const Cell to = cell();
      const bool clear = octile_path_known_free(known, from, to);
      for (const bool cut : {false, true}) {
        DistanceQuery q;
        q.allow_corner_cutting = cut;
        DistanceField field;
        field.compute(known, from, q);
        const double searched = field.distance_m(known.index(to));
        const double octile = octile_distance(from, to) * known.resolution_m();
        if (clear) {
          ASSERT_EQ(searched, octile) << "trial " << trial << " from " << from.x << "," << from.y << " to "
                                      << to.x << "," << to.y << " cut " << cut;
        }
        longer += searched > octile ? 1 : 0;
      }
      held += clear ? 1 : 0;
    }
  }
  EXPECT_GT(held, 500);
  EXPECT_GT(longer, 500);
}

TEST(ArgminLinear, TiesBreakToLowestIndex) {
  Candidates c;
  c.cells = {{0, 0}, {1, 0}, {2, 0}};
  c.feature_count = 2;
  c.features = {2, 1, 1, 2, 3, 0};
  const std::vector<double> w{1, 1};
  EXPECT_EQ(argmin_linear(c, w), 0);  // 3, 3, 3: all tie
  const std::vector<double> w2{0, 1};
  EXPECT_EQ(argmin_linear(c, w2), 2);
  EXPECT_EQ(argmin_linear(Candidates{}, w2), -1);
}

}  // namespace
}  // namespace fsweep
