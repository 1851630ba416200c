// Geodesic distances, the geodesic Hausdorff distance and the frontier choice of equation 12
// (Arvanitakis et al., src/strategies/target_seeking.hpp), on hand-worked ASCII situations.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/config_error.hpp"
#include "strategies/geodesic.hpp"
#include "strategies/registry.hpp"
#include "strategies/strategy_test_utils.hpp"
#include "strategies/target_seeking.hpp"
#include "world/ascii_world.hpp"

namespace fsweep {
namespace test_target_seeking {  // not anonymous: unity builds put it beside other test files' helpers

using nlohmann::json;

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Flags from rows of '.' (in the set) and '#' (outside).
Grid<std::uint8_t> flags(const std::vector<std::string>& rows) {
  Grid<std::uint8_t> g(static_cast<int>(rows[0].size()), static_cast<int>(rows.size()), 0);
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x)
      g.at(Cell{x, y}) = rows[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)] == '.' ? 1 : 0;
  }
  return g;
}

TEST(Geodesic, DistancesBendAroundCellsOutsideTheSet) {
  const Grid<std::uint8_t> g = flags({
      "##..",  //
      "##.#",  //
      "....",  //
  });
  const std::vector<int> source{g.index(Cell{0, 2})};
  const auto d = geodesic_distances(g, source, 1.0);
  auto at = [&](int x, int y) { return d[static_cast<std::size_t>(g.index(Cell{x, y}))]; };
  EXPECT_DOUBLE_EQ(at(0, 2), 0.0);
  EXPECT_DOUBLE_EQ(at(3, 2), 3.0);
  // (1,2) -> (2,1) is a diagonal with one side cell, (2,2), in the set.
  EXPECT_DOUBLE_EQ(at(2, 1), 1.0 + kSqrt2);
  EXPECT_DOUBLE_EQ(at(2, 0), 2.0 + kSqrt2);
  // (2,1) -> (3,0): side (2,0) is in the set; 1 + 2 sqrt2 beats 3 + sqrt2 via (2,0).
  EXPECT_DOUBLE_EQ(at(3, 0), 1.0 + 2.0 * kSqrt2);
  EXPECT_EQ(at(0, 0), kInf);  // outside the set
  // Metres scale with the resolution.
  EXPECT_DOUBLE_EQ(geodesic_distances(g, source, 0.05)[static_cast<std::size_t>(g.index(Cell{3, 0}))],
                   0.05 * (1.0 + 2.0 * kSqrt2));
}

TEST(Geodesic, SealedDiagonalDisconnects) {
  const Grid<std::uint8_t> g = flags({
      ".#",  //
      "#.",  //
  });
  const std::vector<int> source{0};
  const auto d = geodesic_distances(g, source, 1.0);
  EXPECT_EQ(d[3], kInf);
  // A source outside the set is ignored.
  const std::vector<int> outside{1};
  for (const double v : geodesic_distances(g, outside, 1.0)) EXPECT_EQ(v, kInf);
}

TEST(Geodesic, NearestSourceTiesGoToTheSmallerCellIndexPath) {
  // Sources 0 and 4 of a corridor, both 2 cells from cell 2: the search settles cell 1 before
  // cell 3 (equal distance, smaller index), and cell 2 keeps the first path that reached it.
  const Grid<std::uint8_t> g = flags({".....", "##.##", "##.##", "#####", "...##"});
  const std::vector<int> sources{4, 0, 4, -1, 99, g.index(Cell{0, 3})};  // a repeat, 3 ignored
  const GeodesicField f = geodesic_field(g, sources, 0.5);
  const std::vector<int> nearest_row0(f.nearest_source.begin(), f.nearest_source.begin() + 5);
  EXPECT_EQ(nearest_row0, (std::vector<int>{0, 0, 0, 4, 4}));
  EXPECT_DOUBLE_EQ(f.distance_m[2], 1.0);
  // (2,1) is 1 + sqrt2 from both sources (diagonals past cell 2): the path from cell 1 came first.
  EXPECT_EQ(f.nearest_source[static_cast<std::size_t>(g.index(Cell{2, 2}))], 0);
  EXPECT_DOUBLE_EQ(f.distance_m[static_cast<std::size_t>(g.index(Cell{2, 2}))], 0.5 * (2.0 + kSqrt2));
  // Cut off from every source: infinite and -1.
  EXPECT_EQ(f.nearest_source[static_cast<std::size_t>(g.index(Cell{1, 4}))], -1);
  EXPECT_EQ(f.distance_m[static_cast<std::size_t>(g.index(Cell{1, 4}))], kInf);
}

TEST(Geodesic, HausdorffIsTheMinimumOverTheSet) {
  const std::vector<double> field{0.0, 4.0, 2.5, kInf};
  const std::vector<int> set{1, 2, 3};
  EXPECT_DOUBLE_EQ(geodesic_hausdorff(field, set), 2.5);
  const std::vector<int> none{3};
  EXPECT_EQ(geodesic_hausdorff(field, none), kInf);
  EXPECT_EQ(geodesic_hausdorff(field, {}), kInf);
}

// The hand-worked situation. Unknown '?', free '.', occupied '#', the robot R at (5, 3).
// Frontiers: A = {(1,2)} (L = 1) and B = {(8,2), (9,2)} (L = 2) open onto the unknown rows
// 0-1; C = {(5,4)} (L = 1) opens onto the unknown row 5, a region of its own.
const std::vector<std::string> kRooms = {
    "???????????",  //
    "???????????",  //
    "#.######..#",  //
    "#....R....#",  //
    "#####.#####",  //
    "???????????",  //
};

/// Frontier clusters split into single cells (the strategy merges them).
struct Situation : testing::AsciiSituation {
  explicit Situation(std::vector<std::string> rows) : AsciiSituation(std::move(rows), 1.0) {}
};

TargetSeekingParams params_for(Cell target, double w1, double w2, double w3) {
  TargetSeekingParams p;
  p.target = target;
  p.w1 = w1;
  p.w2 = w2;
  p.w3 = w3;
  return p;
}

TEST(TargetSeeking, HausdorffFromTheTargetThroughItsUnknownRegion) {
  Situation s(kRooms);
  const Grid<std::uint8_t> region = unknown_region(s.known, s.frontiers);
  EXPECT_EQ(region[s.at(1, 2)], 1);  // frontier cell
  EXPECT_EQ(region[s.at(2, 3)], 0);  // known free, not frontier
  EXPECT_EQ(region[s.at(0, 2)], 0);  // occupied
  const std::vector<int> target{s.at(3, 0)};
  const auto d = geodesic_distances(region, target, 1.0);
  const std::vector<int> a{s.at(1, 2)};
  const std::vector<int> b{s.at(8, 2), s.at(9, 2)};
  const std::vector<int> c{s.at(5, 4)};
  // (3,0) -> (2,1) -> (1,2): two diagonals.
  EXPECT_DOUBLE_EQ(geodesic_hausdorff(d, a), 2.0 * kSqrt2);
  // (3,0) -> (4,1), three steps east, -> (8,2): octile 3 + 2 sqrt2 (the nearer member).
  EXPECT_DOUBLE_EQ(geodesic_hausdorff(d, b), 3.0 + 2.0 * kSqrt2);
  EXPECT_EQ(geodesic_hausdorff(d, c), kInf);  // another unknown region
}

TEST(TargetSeeking, ChoiceFollowsEquation12ByHand) {
  Situation s(kRooms);
  // Paper defaults (1, 0.9, 0.4). Hg(robot): Euclidean oracle, A sqrt17, B sqrt10.
  //   A: 1/1 + 0.9 * 2 sqrt2 + 0.4 * sqrt17 = 5.1951
  //   B: 1/2 + 0.9 * (3 + 2 sqrt2) + 0.4 * sqrt10 = 7.0104
  // C borders another unknown region and is not eligible.
  const FrontierChoice paper = choose_target_frontier(s.observe(), params_for(Cell{3, 0}, 1.0, 0.9, 0.4));
  ASSERT_EQ(paper.frontiers.size(), 2U);
  EXPECT_EQ(paper.frontiers[0].cells, std::vector<int>{s.at(1, 2)});
  EXPECT_EQ(paper.frontiers[1].cells, (std::vector<int>{s.at(8, 2), s.at(9, 2)}));
  EXPECT_DOUBLE_EQ(paper.frontiers[1].length_m, 2.0);
  EXPECT_DOUBLE_EQ(paper.frontiers[1].hg_robot_m, std::sqrt(10.0));
  EXPECT_NEAR(paper.frontiers[0].score, 1.0 + 0.9 * 2.0 * kSqrt2 + 0.4 * std::sqrt(17.0), 1e-12);
  EXPECT_NEAR(paper.frontiers[1].score, 0.5 + 0.9 * (3.0 + 2.0 * kSqrt2) + 0.4 * std::sqrt(10.0), 1e-12);
  EXPECT_EQ(paper.chosen, 0);
  EXPECT_EQ(paper.goal, s.at(1, 2));

  // Without the target term: A 1 + sqrt17 = 5.123, B 0.5 + sqrt10 = 3.662 -> B. C (1 + 1 = 2)
  // would win if the region filter did not exclude it. Goal in B: (8,2), route
  // sqrt10 + 3 + 2 sqrt2 = 8.99 against (9,2)'s sqrt17 + 4 + 2 sqrt2 = 10.95.
  const FrontierChoice near = choose_target_frontier(s.observe(), params_for(Cell{3, 0}, 1.0, 0.0, 1.0));
  EXPECT_EQ(near.chosen, 1);
  EXPECT_EQ(near.goal, s.at(8, 2));

  // A target in row 5: only C counts.
  const FrontierChoice below = choose_target_frontier(s.observe(), params_for(Cell{0, 5}, 1.0, 0.9, 0.4));
  ASSERT_EQ(below.frontiers.size(), 1U);
  EXPECT_EQ(below.goal, s.at(5, 4));
}

TEST(TargetSeeking, DecidesOneStepAtATimeTowardTheChoice) {
  Situation s(kRooms);
  TargetSeeking strategy(params_for(Cell{3, 0}, 1.0, 0.9, 0.4));
  const Decision d = strategy.decide(s.observe());
  EXPECT_EQ(d.kind, Decision::Kind::GoTo);
  EXPECT_EQ(d.goal, (Cell{1, 2}));
  EXPECT_EQ(d.max_steps, 1);
}

TEST(TargetSeeking, KnownTargetIsReachedByTheWholeShortestPath) {
  Situation s(kRooms);
  TargetSeeking strategy(params_for(Cell{9, 3}, 1.0, 0.9, 0.4));
  const Decision d = strategy.decide(s.observe());
  EXPECT_EQ(d.kind, Decision::Kind::GoTo);
  EXPECT_EQ(d.goal, (Cell{9, 3}));
  EXPECT_EQ(d.max_steps, 0);
  TargetSeeking here(params_for(Cell{5, 3}, 1.0, 0.9, 0.4));
  const Decision done = here.decide(s.observe());
  EXPECT_EQ(done.kind, Decision::Kind::Finish);
  EXPECT_EQ(done.outcome, Decision::Outcome::TargetReached);
}

TEST(TargetSeeking, UnreachableTargetsFinishWithAReason) {
  Situation s(kRooms);
  const auto outcome = [&](Cell target) {
    TargetSeeking strategy(params_for(target, 1.0, 0.9, 0.4));
    return strategy.decide(s.observe());
  };
  const Decision wall = outcome(Cell{0, 3});
  EXPECT_EQ(wall.outcome, Decision::Outcome::TargetUnreachable);
  EXPECT_NE(wall.detail.find("occupied"), std::string::npos) << wall.detail;
  const Decision outside = outcome(Cell{11, 0});
  EXPECT_EQ(outside.outcome, Decision::Outcome::TargetUnreachable);
  EXPECT_NE(outside.detail.find("outside the 11x6 map"), std::string::npos) << outside.detail;
  // Row 5's only frontier cut off from the robot: that region has no reachable frontier.
  s.oracle.unreachable.insert(s.at(5, 4));
  const Decision cut = outcome(Cell{0, 5});
  EXPECT_EQ(cut.kind, Decision::Kind::Finish);
  EXPECT_EQ(cut.outcome, Decision::Outcome::TargetUnreachable);
  EXPECT_NE(cut.detail.find("no reachable frontier"), std::string::npos) << cut.detail;
}

TEST(TargetSeeking, WithoutTargetExploresByLengthAndDistance) {
  Situation s(kRooms);
  TargetSeekingParams p;  // no target: w1 / L + w3 * Hg(robot), every reachable frontier
  // A: 1 + 0.4 sqrt17 = 2.649; B: 0.5 + 0.4 sqrt10 = 1.765; C: 1 + 0.4 * 1 = 1.4 -> C.
  const FrontierChoice c = choose_target_frontier(s.observe(), p);
  ASSERT_EQ(c.frontiers.size(), 3U);
  EXPECT_EQ(c.chosen, 2);
  EXPECT_EQ(c.goal, s.at(5, 4));
  p.w1 = 1.0;
  p.w3 = 0.1;  // A 1.412, B 0.816, C 1.1 -> B; goal: its member nearest the robot
  const FrontierChoice longer = choose_target_frontier(s.observe(), p);
  EXPECT_EQ(longer.chosen, 1);
  EXPECT_EQ(longer.goal, s.at(8, 2));
  TargetSeeking explorer(p);
  const Decision go = explorer.decide(s.observe());
  EXPECT_EQ(go.goal, (Cell{8, 2}));
  EXPECT_EQ(go.max_steps, 0);  // the whole way: nothing to re-aim at
  for (int x = 0; x < 11; ++x) {
    for (int y = 0; y < 6; ++y) s.oracle.unreachable.insert(s.at(x, y));
  }
  const Decision done = explorer.decide(s.observe());
  EXPECT_EQ(done.kind, Decision::Kind::Finish);
  EXPECT_EQ(done.outcome, Decision::Outcome::Explored);
}

TEST(TargetSeekingGradient, WeightsAndObjectiveInACorridorByHand) {
  Situation s({
      "#########",  //
      "?...R...?",  //
      "#########",  //
  });
  const TargetSeekingParams p = params_for(Cell{8, 1}, 1.0, 0.9, 0.4);
  const FrontierChoice c = choose_target_frontier(s.observe(), p);
  ASSERT_EQ(c.chosen, 0);
  ASSERT_EQ(c.frontiers.size(), 1U);  // (1,1) borders the other unknown cell, (0,1)
  EXPECT_EQ(c.frontiers[0].cells, std::vector<int>{s.at(7, 1)});
  const ExplorationField field = exploration_field(s.known, c.frontiers[0].cells, c.from_target_m);
  // f(x) = 1 / ((7 - x) + 1); phi = 1 / (d_g((7,1), target) + 1) = 1/2 everywhere.
  for (int x = 1; x <= 7; ++x) {
    EXPECT_DOUBLE_EQ(field.weight[static_cast<std::size_t>(s.at(x, 1))], 1.0 / (2.0 * (8 - x))) << x;
  }
  EXPECT_EQ(field.weight[static_cast<std::size_t>(s.at(4, 0))], 0.0);  // a wall
  // Range 2: from (4,1) the corridor cells x = 2..6 are in view.
  SensorParams sp;
  sp.range_m = 2.0;
  const Sensor sensor(sp, 1.0);
  const WorldMap view = known_as_world(s.known);
  EXPECT_DOUBLE_EQ(exploration_objective(view, sensor, Cell{4, 1}, 0.0, field.weight),
                   0.5 * (1.0 / 6 + 1.0 / 5 + 1.0 / 4 + 1.0 / 3 + 1.0 / 2));
  // Only the step east brings the robot nearer to the frontier.
  EXPECT_EQ(gradient_step(s.known, sensor, Cell{4, 1}, field), (Cell{5, 1}));
  EXPECT_EQ(gradient_step(s.known, sensor, Cell{7, 1}, field), std::nullopt);  // on A_c
}

TEST(TargetSeekingGradient, StepsAwayFromTheWallAmongProgressingMoves) {
  Situation s({
      "#########",  //
      "#.R.....?",  //
      "#.......?",  //
      "#.......?",  //
      "#.......?",  //
      "#.......?",  //
      "#########",  //
  });
  s.sensor.range_m = 2.0;
  TargetSeekingParams p = params_for(Cell{8, 3}, 1.0, 0.9, 0.4);
  const FrontierChoice c = choose_target_frontier(s.observe(), p);
  ASSERT_EQ(c.chosen, 0);
  const ExplorationField field = exploration_field(s.known, c.frontiers[0].cells, c.from_target_m);
  const Sensor sensor(s.sensor, 1.0);
  const WorldMap view = known_as_world(s.known);
  // East (3,1) and south-east (3,2) both bring the robot one cell nearer to the frontier
  // column x = 7; south-east sees row 4 as well instead of the wall row 0.
  const double east = exploration_objective(view, sensor, Cell{3, 1}, heading_angle(0), field.weight);
  const double south_east = exploration_objective(view, sensor, Cell{3, 2}, heading_angle(1), field.weight);
  EXPECT_GT(south_east, east);
  EXPECT_EQ(gradient_step(s.known, sensor, Cell{2, 1}, field), (Cell{3, 2}));
  p.motion = TargetMotion::Gradient;
  TargetSeeking gradient(p);
  const Decision d = gradient.decide(s.observe());
  EXPECT_EQ(d.goal, (Cell{3, 2}));
  EXPECT_EQ(d.max_steps, 1);
  // Shortest-path motion heads for the goal cell instead: the frontier cell on the shortest
  // estimated route (Euclidean oracle + geodesic from the target): (7,1) 5 + 1 + sqrt2 = 7.41,
  // (7,2) sqrt26 + sqrt2 = 6.51, (7,3) sqrt29 + 1 = 6.39, (7,4) sqrt34 + sqrt2 = 7.25.
  p.motion = TargetMotion::ShortestPath;
  EXPECT_EQ(TargetSeeking(p).decide(s.observe()).goal, (Cell{7, 3}));
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(TargetSeeking, ParametersAreValidatedWithTheirPath) {
  const json resolved = configure_strategy("target_seeking", json{{"target", {4, 7}}}).params;
  EXPECT_EQ(resolved,
            (json{{"target", {4, 7}}, {"w1", 1.0}, {"w2", 0.9}, {"w3", 0.4}, {"motion", "shortest_path"}}));
  EXPECT_EQ(configure_strategy("target_seeking", nullptr).params,
            (json{{"target", nullptr}, {"w1", 1.0}, {"w2", 0.9}, {"w3", 0.4}, {"motion", "shortest_path"}}));
  const std::string weight = error_of([] {
    (void)make_strategy("target_seeking", json{{"target", {1, 1}}, {"w2", 1.5}}, 1, "s");
  });
  EXPECT_NE(weight.find("s/params/w2"), std::string::npos) << weight;
  EXPECT_NE(weight.find("[0, 1]"), std::string::npos) << weight;
  const std::string cell = error_of([] {
    (void)make_strategy("target_seeking", json{{"target", {1.5, 1}}}, 1, "s");
  });
  EXPECT_NE(cell.find("s/params/target"), std::string::npos) << cell;
  EXPECT_EQ(
      configure_strategy("target_seeking", json{{"target", {1, 1}}, {"motion", "gradient"}}).params["motion"],
      "gradient");
  const std::string motion = error_of([] {
    (void)make_strategy("target_seeking", json{{"target", {1, 1}}, {"motion", "fly"}}, 1, "s");
  });
  EXPECT_NE(motion.find("s/params/motion"), std::string::npos) << motion;
  const std::string key = error_of([] {
    (void)make_strategy("target_seeking", json{{"target", {1, 1}}, {"w4", 0}}, 1, "s");
  });
  EXPECT_NE(key.find("w4"), std::string::npos) << key;
}

}  // namespace test_target_seeking
}  // namespace fsweep
