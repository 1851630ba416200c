// Hand-worked situations for Mei 2006's target selection rules: orientation (section IV-B,
// Figures 3(b) and 4) and the widest-frontier baseline (section V-C).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "core/config_error.hpp"
#include "strategies/orientation.hpp"
#include "strategies/registry.hpp"
#include "strategies/sensing_region.hpp"
#include "strategies/strategy_test_utils.hpp"
#include "strategies/widest_frontier.hpp"
#include "world/sensor.hpp"

namespace fsweep {
namespace test_mei_strategies {  // not anonymous: unity builds put it beside other test files' helpers

/// An ASCII situation (testing::AsciiSituation) with Mei's sensor range d_s and a heading.
struct Situation : testing::AsciiSituation {
  Situation(const std::vector<std::string>& rows, double d_s, int heading_in) : AsciiSituation(rows) {
    sensor.range_m = d_s;
    heading = heading_in;
  }
};

constexpr int kEast = 0;
constexpr int kSouth = 2;
constexpr int kNorth = 6;

// Figure 3(b): the robot R at (3, 3); the explored area holds exactly five frontier cells,
// (2,2), (3,1), (3,2), (2,4), (4,4), of which (2,2), (3,1), (3,2) are connected. The paper's
// (i, j) are read as (x, y) with y growing downward (our screen convention); the figure's
// obstacles are not given in the text, so the walls below are chosen to make exactly those
// five cells frontiers.
const std::vector<std::string> kFigure3b = {
    "???????",  //
    "?#?.##?",  //
    "?#..#??",  //
    "?#.R.#?",  //
    "?#.#.#?",  //
    "???#???",  //
    "???????",  //
};

// Figure 4: 25 explored cells (5 x 5 around the robot), the rest unknown; 8 frontier cells
// numbered clockwise from the robot's left; the cell at the robot's left is an obstacle.
// The robot faces north (up), so its left is west. Cells 1..8 (offsets from R):
// (-2,-1) (-2,-2) (-1,-2) (0,-2) (1,-2) (2,-2) (2,-1) (2,0); the rest of the ring is walls.
const std::vector<std::string> kFigure4 = {
    "???????????",  //
    "???????????",  //
    "???????????",  //
    "???.....???",  //
    "???.....???",  //
    "???#.R..???",  //
    "???#...#???",  //
    "???#####???",  //
    "???????????",  //
    "???????????",  //
    "???????????",  //
};

std::vector<Cell> figure4_cells_1_to_8() {
  return {{3, 4}, {3, 3}, {4, 3}, {5, 3}, {6, 3}, {7, 3}, {7, 4}, {7, 5}};
}

TEST(MeiFigure3b, HasTheFiveFrontierCellsOfThePaper) {
  Situation s(kFigure3b, 3.0, kNorth);
  const std::vector<Cell> expected = {{3, 1}, {2, 2}, {3, 2}, {2, 4}, {4, 4}};  // ascending index
  EXPECT_EQ(s.as_cells(s.frontiers.cells()), expected);
}

TEST(MeiFigure4, HasEightFrontierCellsAndAWallAtTheLeft) {
  Situation s(kFigure4, 4.0, kNorth);
  EXPECT_EQ(s.frontiers.count(), 8);
  EXPECT_EQ(s.known.state(Cell{3, 5}), CellState::Occupied);  // directly left of R (5,5)
}

TEST(Orientation, Figure4ListsTheCellsClockwiseFromTheLeft) {
  Situation s(kFigure4, 4.0, kNorth);
  const auto f = s.frontiers.cells();
  EXPECT_EQ(s.as_cells(clockwise_from_left(s.known, s.robot, kNorth, f)), figure4_cells_1_to_8());
}

TEST(Orientation, Figure4StopsBeforeSevenTenthsOfTheSensingRange) {
  // d_s = 4: 0.7 d_s = 2.8. From the head, cell 1 (3,4): cell 4 (5,3) is sqrt(5) = 2.24 away,
  // cell 5 (6,3) sqrt(10) = 3.16: the walk ends at cell 4, straight ahead of the robot.
  Situation s(kFigure4, 4.0, kNorth);
  Orientation o{OrientationParams{}};
  const Decision d = o.decide(s.observe());
  ASSERT_EQ(d.kind, Decision::Kind::GoTo);
  EXPECT_EQ(d.goal, (Cell{5, 3}));
  // d_s = 10 (the paper's): every cell is within 7 of the head; the walk reaches cell 8.
  Situation wide(kFigure4, 10.0, kNorth);
  EXPECT_EQ(o.decide(wide.observe()).goal, (Cell{7, 5}));
}

TEST(Orientation, HeadingRotatesTheList) {
  // Facing east the left is north: the list starts at cell 4 (5,3), runs 5, 6, 7, 8 and then
  // wraps to 1, 2, 3. With d_s = 4 the walk stops before cell 8 (2.83 >= 2.8 from the head).
  Situation s(kFigure4, 4.0, kEast);
  const auto c = figure4_cells_1_to_8();
  const std::vector<Cell> expected = {c[3], c[4], c[5], c[6], c[7], c[0], c[1], c[2]};
  EXPECT_EQ(s.as_cells(clockwise_from_left(s.known, s.robot, kEast, s.frontiers.cells())), expected);
  Orientation o{OrientationParams{}};
  EXPECT_EQ(o.decide(s.observe()).goal, c[6]);
}

TEST(Orientation, Figure3bFacingNorth) {
  // Left = west. Clockwise: (2,2) (north-west), then (3,2) and (3,1) at the same angle (north;
  // nearer first), then (4,4) (south-east), (2,4) (south-west). d_s = 3 (0.7 d_s = 2.1): the
  // walk goes (2,2) -> (3,2) -> (3,1) (sqrt 2 from the head) and stops at the jump to (4,4).
  Situation s(kFigure3b, 3.0, kNorth);
  const std::vector<Cell> order = {{2, 2}, {3, 2}, {3, 1}, {4, 4}, {2, 4}};
  EXPECT_EQ(s.as_cells(clockwise_from_left(s.known, s.robot, kNorth, s.frontiers.cells())), order);
  Orientation o{OrientationParams{}};
  EXPECT_EQ(o.decide(s.observe()).goal, (Cell{3, 1}));
}

TEST(Orientation, DistanceFromTheHeadMustStayBelowTheLimit) {
  // As above with d_s = 2: 0.7 d_s = 1.4 and (3,1) is sqrt 2 = 1.414 from the head: stop at (3,2).
  Situation s(kFigure3b, 2.0, kNorth);
  Orientation o{OrientationParams{}};
  EXPECT_EQ(o.decide(s.observe()).goal, (Cell{3, 2}));
  // head_distance_ratio 1: the limit 2 admits (3,1).
  OrientationParams whole;
  whole.head_distance_ratio = 1.0;
  Orientation wide{whole};
  EXPECT_EQ(wide.decide(s.observe()).goal, (Cell{3, 1}));
}

TEST(Orientation, NoJumpKeepsTheHead) {
  // Facing south the left is east: the list is (4,4), (2,4), (2,2), (3,2), (3,1). (2,4) is two
  // columns from the head: a jump, so the target is the head itself.
  Situation s(kFigure3b, 3.0, kSouth);
  const std::vector<Cell> order = {{4, 4}, {2, 4}, {2, 2}, {3, 2}, {3, 1}};
  EXPECT_EQ(s.as_cells(clockwise_from_left(s.known, s.robot, kSouth, s.frontiers.cells())), order);
  Orientation o{OrientationParams{}};
  EXPECT_EQ(o.decide(s.observe()).goal, (Cell{4, 4}));
}

TEST(Orientation, UnreachableCellsInTheRegionAreIgnored) {
  // As NoJumpKeepsTheHead with (4,4) unreachable: the head is (2,4), then a jump to (2,2).
  Situation s(kFigure3b, 3.0, kSouth);
  s.oracle.unreachable.insert(s.at(4, 4));
  Orientation o{OrientationParams{}};
  EXPECT_EQ(o.decide(s.observe()).goal, (Cell{2, 4}));
}

// A corridor open at both ends: frontier cells (1,1) (7 from R) and (14,1) (6 from R).
const std::vector<std::string> kCorridor = {
    "?##############?",  //
    "?.......R......?",  //
    "?##############?",  //
};

TEST(MeiStrategies, NoFrontierInTheRegionGoesToTheClosestOutside) {
  for (const std::string name : {"orientation", "widest_frontier"}) {
    Situation s(kCorridor, 3.0, kEast);
    auto strategy = make_strategy(name, nullptr, 1, "strategy");
    EXPECT_EQ(strategy->decide(s.observe()).goal, (Cell{14, 1})) << name;
    s.oracle.unreachable.insert(s.at(14, 1));
    EXPECT_EQ(strategy->decide(s.observe()).goal, (Cell{1, 1})) << name;
    s.oracle.unreachable.insert(s.at(1, 1));
    EXPECT_EQ(strategy->decide(s.observe()).kind, Decision::Kind::Finish) << name;
  }
}

TEST(MeiStrategies, NoFrontierLeftFinishes) {
  const std::vector<std::string> closed = {"#####", "#.R.#", "#####"};
  for (const std::string name : {"orientation", "widest_frontier"}) {
    Situation s(closed, 10.0, kEast);
    EXPECT_EQ(make_strategy(name, nullptr, 1, "strategy")->decide(s.observe()).kind, Decision::Kind::Finish);
  }
}

TEST(WidestFrontier, Figure3bTakesTheMiddleOfTheConnectedThree) {
  // Groups: {(3,1), (2,2), (3,2)}, {(2,4)}, {(4,4)}. The centroid of the three is (8/3, 5/3);
  // (3,2) is nearest (0.47 against 0.75 for the others).
  Situation s(kFigure3b, 3.0, kNorth);
  const auto groups = frontier_groups(s.known, s.frontiers.cells());
  ASSERT_EQ(groups.size(), 3U);
  EXPECT_EQ(s.as_cells(groups[0]), (std::vector<Cell>{{3, 1}, {2, 2}, {3, 2}}));
  WidestFrontier w;
  EXPECT_EQ(w.decide(s.observe()).goal, (Cell{3, 2}));
}

TEST(WidestFrontier, Figure4TakesTheCellNearestTheCentroid) {
  // One group of 8; centroid offset (0.25, -1.5) from R: nearest is cell 4 (5,3).
  Situation s(kFigure4, 10.0, kNorth);
  WidestFrontier w;
  EXPECT_EQ(w.decide(s.observe()).goal, (Cell{5, 3}));
}

TEST(WidestFrontier, EqualGroupsBreakToTheLowestIndex) {
  // Two frontiers of two cells each, west (1,1)-(1,2) and east (5,1)-(5,2): the west one has
  // the lowest index; its middle is a tie broken to the lowest index, (1,1).
  const std::vector<std::string> rows = {"#######", "?..R..?", "?.....?", "#######"};
  Situation s(rows, 10.0, kEast);
  WidestFrontier w;
  EXPECT_EQ(w.decide(s.observe()).goal, (Cell{1, 1}));
}

// A corridor cut by a wall at (3,1): the cells beyond it, (1,1) and (2,1), are known (seen
// before), so (1,1) is a frontier cell 3 cells from R, within d_s = 5 but out of view; (7,1)
// is 3 cells the other way, in view.
const std::vector<std::string> kWalledCorridor = {
    "#########",  //
    "?..#R...?",  //
    "#########",  //
};

TEST(SensingRegion, VisibleKeepsOnlyTheFrontierCellsInView) {
  Situation s(kWalledCorridor, 5.0, kEast);
  const SensingRegion disc = split_by_sensing_region(s.observe());
  EXPECT_EQ(s.as_cells(disc.inside), (std::vector<Cell>{{1, 1}, {7, 1}}));
  SensingRegionRule rule;
  rule.region = "visible";
  const SensingRegion visible = split_by_sensing_region(s.observe(), rule);
  EXPECT_EQ(s.as_cells(visible.inside), (std::vector<Cell>{{7, 1}}));
  EXPECT_EQ(s.as_cells(visible.outside), (std::vector<Cell>{{1, 1}}));  // still a goal for step 4
  // The ray rule of the sensor on the known map: the wall blocks, unknown cells do not.
  EXPECT_FALSE(centre_ray_clear(s.known, s.robot, Cell{1, 1}));
  EXPECT_TRUE(centre_ray_clear(s.known, s.robot, Cell{8, 1}));
}

// An enclosed pocket of 3 unknown cells (3,2)-(3,4) behind walls, its rim (4,1)-(4,5) five
// frontier cells, and the open unknown beyond column 9 (16 cells) with four frontier cells
// (8,2)-(8,5).
const std::vector<std::string> kPocket = {
    "##########??",  //
    "#.##.....#??",  //
    "#.#?.....#??",  //
    "#.#?.....???",  //
    "#.#?.....???",  //
    "#.##.R...#??",  //
    "##########??",  //
};

TEST(SensingRegion, PocketRimsLeaveTheRegionUpToTheirSize) {
  Situation s(kPocket, 10.0, kEast);
  const std::vector<Cell> rim = {{4, 1}, {4, 2}, {8, 2}, {4, 3}, {8, 3}, {4, 4}, {8, 4}, {4, 5}, {8, 5}};
  EXPECT_EQ(s.as_cells(split_by_sensing_region(s.observe()).inside), rim);
  SensingRegionRule rule;
  for (const int cells : {3, 15}) {  // the pocket's 3 cells, or up to 15: the open region has 16
    rule.pocket_cells = cells;
    const SensingRegion r = split_by_sensing_region(s.observe(), rule);
    EXPECT_EQ(s.as_cells(r.inside), (std::vector<Cell>{{8, 2}, {8, 3}, {8, 4}, {8, 5}})) << cells;
    EXPECT_EQ(r.outside.size(), 5U) << cells;
  }
  rule.pocket_cells = 2;  // smaller than the pocket: every rim stays
  EXPECT_EQ(s.as_cells(split_by_sensing_region(s.observe(), rule).inside), rim);
  rule.pocket_cells = 16;  // the open region counts as a pocket too: nothing is left
  EXPECT_TRUE(split_by_sensing_region(s.observe(), rule).inside.empty());
  // Through the registry: widest frontier goes to the middle of the rim (5 cells against 4)
  // by default, to the open frontier when rims of pockets up to 3 cells are left out.
  EXPECT_EQ(make_strategy("widest_frontier", nullptr, 1, "strategy")->decide(s.observe()).goal, (Cell{4, 3}));
  EXPECT_EQ(make_strategy("widest_frontier", {{"pocket_cells", 3}}, 1, "strategy")->decide(s.observe()).goal,
            (Cell{8, 3}));
}

TEST(ClosestFrontier, GoalCellIsTheNearestFrontierCellNotTheNearestClustersRepresentative) {
  // One cluster: row 1, ten frontier cells under the unknown row 0. Its representative, the
  // member nearest the centroid (4.5, 1), is (4,1) (a tie with (5,1) to the lower index); the
  // nearest frontier cell to R (0,2) is (0,1) (Holz 2010 eq. 2).
  const std::vector<std::string> rows = {"??????????", "..........", "R.........", "##########"};
  Situation s(rows, 3.0, kEast);
  ASSERT_EQ(s.clusters.size(), 1U);
  EXPECT_EQ(make_strategy("closest_frontier", nullptr, 1, "strategy")->decide(s.observe()).goal,
            (Cell{4, 1}));
  const auto by_cell = make_strategy("closest_frontier", {{"goal", "cell"}}, 1, "strategy");
  EXPECT_EQ(by_cell->decide(s.observe()).goal, (Cell{0, 1}));
  // Its candidates are the ten cells, each with its own distance.
  auto* linear = dynamic_cast<LinearScoredStrategy*>(by_cell.get());
  ASSERT_NE(linear, nullptr);
  EXPECT_EQ(linear->candidates(s.observe()).cells.size(), 10U);
  // Recorded only when set.
  EXPECT_EQ(configure_strategy("closest_frontier", nullptr).params, (nlohmann::json{{"distance", "path"}}));
  EXPECT_THROW((void)configure_strategy("closest_frontier", {{"goal", "room"}}, "p"), ConfigError);
}

TEST(MeiStrategies, ParamsAreValidated) {
  EXPECT_DOUBLE_EQ(orientation_params().read(nullptr, "p").head_distance_ratio, 0.7);
  EXPECT_DOUBLE_EQ(orientation_params().read({{"head_distance_ratio", 1.0}}, "p").head_distance_ratio, 1.0);
  EXPECT_THROW((void)orientation_params().read({{"head_distance_ratio", 0.0}}, "p"), ConfigError);
  EXPECT_THROW((void)orientation_params().read({{"head_distance_ratio", 1.5}}, "p"), ConfigError);
  EXPECT_THROW((void)orientation_params().read({{"head_distance_ratio", "x"}}, "p"), ConfigError);
  EXPECT_THROW((void)orientation_params().read({{"jump_ratio", 0.5}}, "p"), ConfigError);
  EXPECT_THROW((void)configure_strategy("widest_frontier", {{"w1", 1}}, "p"), ConfigError);
  EXPECT_NO_THROW((void)configure_strategy("widest_frontier", nlohmann::json::object(), "p"));
  try {
    (void)make_strategy("orientation", {{"head_distance_ratio", 2}}, 1, "strategy");
    FAIL();
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("strategy/params/head_distance_ratio"), std::string::npos) << what;
    EXPECT_NE(what.find("(0, 1]"), std::string::npos) << what;
  }
  EXPECT_EQ(configure_strategy("orientation", nullptr).params,
            (nlohmann::json{{"head_distance_ratio", 0.7}}));
  EXPECT_EQ(configure_strategy("widest_frontier", nullptr).params, nlohmann::json::object());
  // The sensing-region options are recorded only when set, so older run keys hold.
  EXPECT_EQ(configure_strategy("orientation", {{"region", "visible"}, {"pocket_cells", 30}}).params,
            (nlohmann::json{{"head_distance_ratio", 0.7}, {"region", "visible"}, {"pocket_cells", 30}}));
  EXPECT_THROW((void)configure_strategy("widest_frontier", {{"region", "cone"}}, "p"), ConfigError);
  EXPECT_THROW((void)configure_strategy("widest_frontier", {{"pocket_cells", -1}}, "p"), ConfigError);
}

TEST(MeiStrategies, RegisteredAndCloneable) {
  Situation s(kFigure4, 4.0, kNorth);
  for (const std::string name : {"orientation", "widest_frontier"}) {
    auto a = make_strategy(name, nullptr, 1, "strategy");
    EXPECT_EQ(a->name(), name);
    auto b = a->clone();
    EXPECT_EQ(b->name(), name);
    EXPECT_EQ(a->decide(s.observe()).goal, b->decide(s.observe()).goal);
  }
}

}  // namespace test_mei_strategies
}  // namespace fsweep
