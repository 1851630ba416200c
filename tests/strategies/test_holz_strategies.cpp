// Hand-worked situations for the strategies evaluated by Holz, Basilico, Amigoni 2010:
// González-Baños and Latombe (gbl, section IV-B), MCDM (section IV-C) and random frontier;
// and every registered strategy run end to end with every registered planner.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "core/config_error.hpp"
#include "planners/registry.hpp"
#include "sim/simulation.hpp"
#include "strategies/choquet.hpp"
#include "strategies/gbl.hpp"
#include "strategies/mcdm.hpp"
#include "strategies/random_frontier.hpp"
#include "strategies/registry.hpp"
#include "strategies/strategy_test_utils.hpp"
#include "world/ascii_world.hpp"
#include "world/map_spec.hpp"

namespace fsweep {
namespace test_holz_strategies {  // not anonymous: unity builds put it beside other test files' helpers

// A corridor (row 2) between walls, open at both ends. R = (6, 2).
//   left end:  (1,2) free, (0,1) (0,2) (0,3) unknown        -> frontier cell (1,2)
//   right end: (7..10, 2) free, (10,1) (11,1) (11,2) (11,3) (10,3) unknown
//              -> frontier cells (9,2) (diagonals to (10,1), (10,3)) and (10,2)
// With a 1.5 m range (3 x 3 block, resolution 1 m) the scans count, by hand:
//   (1,2):  unknown (0,1) (0,2) (0,3) = 3; known: itself, (1,1) (2,1) (2,2) (1,3) (2,3) = 6
//   (9,2):  unknown (10,1) (10,3) = 2;       known: itself + 6 = 7
//   (10,2): unknown (10,1) (11,1) (11,2) (11,3) (10,3) = 5; known: itself, (9,1) (9,2) (9,3) = 4
// (no diagonal has both cells beside it occupied, so every cell of each block is in sight).
// Euclidean path lengths from R along the row: (1,2) 5 m, (9,2) 3 m, (10,2) 4 m.
const std::vector<std::string> kCorridor = {
    "############",  //
    "?#########??",  //
    "?.....R....?",  //
    "?#########??",  //
    "############",  //
};

/// An ASCII situation (testing::AsciiSituation) seen with a sensor of range_m.
struct Situation : testing::AsciiSituation {
  /// `cluster_max_length_m` as FrontierMap::clusters (<= 0: whole components).
  Situation(const std::vector<std::string>& rows, double range_m, double cluster_max_length_m = 0.0)
      : AsciiSituation(rows, cluster_max_length_m) {
    sensor.range_m = range_m;
  }
};

std::set<std::pair<int, int>> cells_of(const std::vector<GblCandidate>& c) {
  std::set<std::pair<int, int>> out;
  for (const auto& k : c) out.insert({k.cell.x, k.cell.y});
  return out;
}

Gbl make_gbl(double radius_m, double lambda, int samples = 200, std::uint64_t seed = 5) {
  GblParams p;
  p.radius_m = radius_m;
  p.lambda = lambda;
  p.samples = samples;
  return Gbl(p, seed);
}

// ---------------------------------------------------------------- gbl

TEST(Gbl, CorridorClustersAndFrontierCells) {
  Situation s(kCorridor, 1.5);
  ASSERT_EQ(s.clusters.size(), 2U);
  EXPECT_EQ(s.clusters[0].cells, (std::vector<int>{s.at(1, 2)}));
  EXPECT_EQ(s.clusters[1].cells, (std::vector<int>{s.at(9, 2), s.at(10, 2)}));
}

TEST(Gbl, RadiusZeroSamplesTheFrontierCellsWithHandCountedGains) {
  // 200 draws over 3 frontier cells: the seed's draws hit all three.
  Situation s(kCorridor, 1.5);
  Gbl gbl = make_gbl(0.0, 0.2);
  const auto c = gbl.candidates(s.observe());
  ASSERT_EQ(cells_of(c), (std::set<std::pair<int, int>>{{1, 2}, {9, 2}, {10, 2}}));
  std::map<std::pair<int, int>, std::pair<double, double>> by_cell;  // (L, I)
  for (const auto& k : c) by_cell[{k.cell.x, k.cell.y}] = {k.length_m, k.gain_m2};
  EXPECT_EQ(by_cell[(std::pair{1, 2})], (std::pair{5.0, 3.0}));
  EXPECT_EQ(by_cell[(std::pair{9, 2})], (std::pair{3.0, 2.0}));
  EXPECT_EQ(by_cell[(std::pair{10, 2})], (std::pair{4.0, 5.0}));
}

TEST(Gbl, UtilityTradesGainAgainstTravel) {
  // Equation 3, u = I exp(-lambda L):
  //   lambda 0.2: (1,2) 3 e^-1 = 1.104, (9,2) 2 e^-0.6 = 1.098, (10,2) 5 e^-0.8 = 2.247 -> (10,2)
  //   lambda 2:   (1,2) 3 e^-10 = 1.4e-4, (9,2) 2 e^-6 = 5.0e-3, (10,2) 5 e^-8 = 1.7e-3 -> (9,2)
  //   lambda 0:   the largest gain, (10,2)
  for (const auto& [lambda, goal] :
       std::vector<std::pair<double, Cell>>{{0.2, {10, 2}}, {2.0, {9, 2}}, {0.0, {10, 2}}}) {
    Situation s(kCorridor, 1.5);
    Gbl gbl = make_gbl(0.0, lambda);
    const Decision d = gbl.decide(s.observe());
    EXPECT_EQ(d.kind, Decision::Kind::GoTo);
    EXPECT_EQ(d.goal, goal) << "lambda " << lambda;
  }
}

TEST(Gbl, BestBreaksTiesToTheLowestPositionAndSkipsZeroGain) {
  const std::vector<GblCandidate> c = {
      {{0, 0}, 1.0, 0.0},   // no gain: never chosen, even though nearest
      {{1, 0}, 2.0, 4.0},   // 4 e^-0.4
      {{2, 0}, 2.0, 4.0},   // the same utility: the earlier one wins
      {{3, 0}, 50.0, 9.0},  // 9 e^-10
  };
  EXPECT_EQ(Gbl::best(c, 0.2), 1);
  EXPECT_EQ(Gbl::best({c[0]}, 0.2), -1);
  // No underflow: e^-0.2*5000 is 0 in double, the log form still ranks 2 > 1 by gain.
  EXPECT_EQ(Gbl::best({{{0, 0}, 5000.0, 1.0}, {{1, 0}, 5000.0, 2.0}}, 0.2), 1);
}

TEST(Gbl, CandidatesAreKnownFreeCellsNearTheFrontierAndNeverTheRobotCell) {
  // radius 1 m: the free cells within 1 of (1,2): (1,2) (2,2); of (9,2) and (10,2): (8,2)
  // (9,2) (10,2). 200 draws hit all five. Moving R onto (8,2) removes it.
  Situation s(kCorridor, 1.5);
  Gbl gbl = make_gbl(1.0, 0.2);
  EXPECT_EQ(cells_of(gbl.candidates(s.observe())),
            (std::set<std::pair<int, int>>{{1, 2}, {2, 2}, {8, 2}, {9, 2}, {10, 2}}));
  s.move_robot(Cell{8, 2});
  EXPECT_EQ(cells_of(gbl.candidates(s.observe())),
            (std::set<std::pair<int, int>>{{1, 2}, {2, 2}, {9, 2}, {10, 2}}));
}

TEST(Gbl, FollowsTheClustersItIsGiven) {
  // A filter upstream (e.g. map segmentation) that leaves only the left cluster: the better
  // right end is not considered.
  Situation s(kCorridor, 1.5);
  s.clusters.erase(s.clusters.begin() + 1);
  Gbl gbl = make_gbl(1.0, 0.2);
  EXPECT_EQ(cells_of(gbl.candidates(s.observe())), (std::set<std::pair<int, int>>{{1, 2}, {2, 2}}));
  EXPECT_EQ(gbl.decide(s.observe()).goal, (Cell{1, 2}));  // (2,2) sees no unknown cell
}

TEST(Gbl, KeepsToTheRobotsSegmentWhenTheEngineRestrictsIt) {
  // A segment mask (the `seg` heuristic) flagging the corridor's left part x <= 5: only the
  // left frontier cell and the free cells near it in the segment. A mask without any frontier
  // cell in it is ignored.
  Situation s(kCorridor, 1.5);
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(s.known.size()), 0);
  for (int x = 1; x <= 5; ++x) mask[static_cast<std::size_t>(s.at(x, 2))] = 1;
  Gbl gbl = make_gbl(1.0, 0.2);
  Observation obs = s.observe();
  obs.segment_mask = &mask;
  EXPECT_EQ(cells_of(gbl.candidates(obs)), (std::set<std::pair<int, int>>{{1, 2}, {2, 2}}));
  mask[static_cast<std::size_t>(s.at(1, 2))] = 0;  // now no frontier cell in the segment
  EXPECT_EQ(cells_of(gbl.candidates(obs)),
            (std::set<std::pair<int, int>>{{1, 2}, {2, 2}, {8, 2}, {9, 2}, {10, 2}}));
}

TEST(Gbl, UnreachableCandidatesAreDropped) {
  Situation s(kCorridor, 1.5);
  s.oracle.unreachable = {s.at(10, 2)};
  Gbl gbl = make_gbl(0.0, 0.2);
  // Left: (1,2) 1.104 vs (9,2) 1.098 (see UtilityTradesGainAgainstTravel).
  EXPECT_EQ(gbl.decide(s.observe()).goal, (Cell{1, 2}));
}

TEST(Gbl, NoGainFallsBackToTheNearestRepresentativeAndNoneReachableFinishes) {
  // A 0.5 m range sees only the cell itself: no candidate has gain. The representatives are
  // (1,2) at 5 m and (9,2) at 3 m (the right cluster's centroid (9.5, 2) is equally near both
  // members: the lower index).
  Situation s(kCorridor, 0.5);
  Gbl gbl = make_gbl(1.0, 0.2);
  EXPECT_EQ(gbl.decide(s.observe()).goal, (Cell{9, 2}));
  for (int x = 0; x < 12; ++x) s.oracle.unreachable.insert(s.at(x, 2));
  EXPECT_EQ(gbl.decide(s.observe()).kind, Decision::Kind::Finish);
  Situation none({"###", "#R#", "###"}, 1.5);
  EXPECT_EQ(gbl.decide(none.observe()).kind, Decision::Kind::Finish);
}

TEST(Gbl, AGoalWhoseTripRevealedNothingIsNotDrawnAgain) {
  Situation s(kCorridor, 1.5);
  Gbl gbl = make_gbl(0.0, 0.2);
  (void)gbl.decide(s.observe());  // at (6,2): goes to (10,2)
  s.move_robot(Cell{10, 2});
  s.previous_goal = Cell{10, 2};
  (void)gbl.decide(s.observe());  // arrived, nothing revealed (the known map is unchanged)
  s.move_robot(Cell{6, 2});
  s.previous_goal = Cell{9, 2};
  const auto c = gbl.candidates(s.observe());
  EXPECT_EQ(cells_of(c), (std::set<std::pair<int, int>>{{1, 2}, {9, 2}}));
  // A trip that revealed something does not count.
  Situation t(kCorridor, 1.5);
  Gbl fresh = make_gbl(0.0, 0.2);
  (void)fresh.decide(t.observe());
  t.known.reveal(t.at(11, 1), true);  // seen on the way
  t.move_robot(Cell{10, 2});
  t.previous_goal = Cell{10, 2};
  (void)fresh.decide(t.observe());
  t.move_robot(Cell{6, 2});
  t.previous_goal = Cell{9, 2};
  EXPECT_EQ(cells_of(fresh.candidates(t.observe())),
            (std::set<std::pair<int, int>>{{1, 2}, {9, 2}, {10, 2}}));
}

TEST(Gbl, DeterministicForASeedAndCloneCopiesTheGenerator) {
  Situation s(kCorridor, 1.5);
  Gbl a = make_gbl(1.0, 0.2, 7, 11);
  Gbl b = make_gbl(1.0, 0.2, 7, 11);
  const auto ca = a.candidates(s.observe());
  const auto cb = b.candidates(s.observe());
  ASSERT_EQ(ca.size(), cb.size());
  for (std::size_t k = 0; k < ca.size(); ++k) EXPECT_EQ(ca[k].cell, cb[k].cell);
  EXPECT_TRUE(a == b);
  // Mid-run clone: the same next draws.
  auto clone = a.clone();
  EXPECT_TRUE(a == dynamic_cast<const Gbl&>(*clone));
  for (int k = 0; k < 5; ++k) EXPECT_EQ(a.decide(s.observe()).goal, clone->decide(s.observe()).goal);
  EXPECT_TRUE(a == dynamic_cast<const Gbl&>(*clone));
  // Another seed draws another sequence (7 draws over 5 cells: the first-occurrence orders
  // of seeds 11 and 12 differ).
  Gbl c = make_gbl(1.0, 0.2, 7, 12);
  Gbl d = make_gbl(1.0, 0.2, 7, 11);
  std::vector<Cell> oc;
  std::vector<Cell> od;
  for (const auto& k : c.candidates(s.observe())) oc.push_back(k.cell);
  for (const auto& k : d.candidates(s.observe())) od.push_back(k.cell);
  EXPECT_NE(oc, od);
  EXPECT_FALSE(c == d);
}

TEST(Gbl, FieldOfViewUsesTheDirectionFromTheRobot) {
  // 90 degree field of view. From R = (6,2), (10,2) is straight east: facing east it sees
  // (11,1) (11,2) (11,3) ((10,1) and (10,3) are at +-90 degrees, outside +-45) = 3 unknown.
  // (1,2) is straight west: it sees (0,1) (0,2) (0,3) = 3.
  Situation s(kCorridor, 1.5);
  s.sensor.fov_deg = 90.0;
  Gbl gbl = make_gbl(0.0, 0.2);
  std::map<std::pair<int, int>, double> gain;
  for (const auto& k : gbl.candidates(s.observe())) gain[{k.cell.x, k.cell.y}] = k.gain_m2;
  EXPECT_EQ(gain[(std::pair{10, 2})], 3.0);
  EXPECT_EQ(gain[(std::pair{1, 2})], 3.0);
  // (9,2) facing east: its unknown diagonals (10,1) and (10,3) lie at -45 and +45 degrees,
  // on the (inclusive) boundary: 2.
  EXPECT_EQ(gain[(std::pair{9, 2})], 2.0);
  EXPECT_DOUBLE_EQ(GainScanner::scan_heading(s.observe(), Cell{1, 2}), M_PI);
  s.heading = 2;
  EXPECT_DOUBLE_EQ(GainScanner::scan_heading(s.observe(), s.robot), M_PI / 2.0);
}

TEST(Gbl, ParamsAreValidatedAndResolved) {
  const GblParams d = gbl_params().read(nullptr, "p");
  EXPECT_EQ(d.samples, 30);
  EXPECT_DOUBLE_EQ(d.radius_m, 1.0);
  EXPECT_DOUBLE_EQ(d.lambda, 0.2);
  EXPECT_EQ(configure_strategy("gbl", nullptr).params,
            (nlohmann::json{{"samples", 30}, {"radius_m", 1.0}, {"lambda", 0.2}}));
  EXPECT_EQ(configure_strategy("gbl", {{"samples", 5}}).params,
            (nlohmann::json{{"samples", 5}, {"radius_m", 1.0}, {"lambda", 0.2}}));
  for (const auto& bad :
       {nlohmann::json{{"samples", 0}}, nlohmann::json{{"samples", 2.5}}, nlohmann::json{{"radius_m", -1}},
        nlohmann::json{{"lambda", "x"}}, nlohmann::json{{"lambda", -0.1}}, nlohmann::json{{"seed", 1}}}) {
    EXPECT_THROW((void)gbl_params().read(bad, "p"), ConfigError) << bad.dump();
  }
  try {
    (void)make_strategy("gbl", {{"samples", 0}, {"lambda", -1}}, 1, "strategy");
    FAIL();
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("strategy/params/samples"), std::string::npos) << what;
    EXPECT_NE(what.find("[1, 100000]"), std::string::npos) << what;
    EXPECT_NE(what.find("strategy/params/lambda"), std::string::npos) << what;
  }
}

// ---------------------------------------------------------------- mcdm

TEST(Mcdm, HandWorkedTableIDecision) {
  // Clusters split into single cells (1 m pieces): candidates (1,2), (9,2), (10,2) (cluster
  // order). Criteria (counts above, resolution 1 m so m^2 = cells):
  //   A (1,2):  L 5, I 3, O 6      B (9,2): L 3, I 2, O 7      C (10,2): L 4, I 5, O 4
  // Equation 5 and analogues: L in [3, 5], I in [2, 5], O in [4, 7]:
  //   A: u_L 0,   u_I 1/3, u_O 2/3
  //   B: u_L 1,   u_I 0,   u_O 1
  //   C: u_L 1/2, u_I 1,   u_O 0
  // Choquet with Table I (L .2, I .4, O .4, LI .9, LO .6, IO .8):
  //   A: sorted L 0 <= I 1/3 <= O 2/3: 0 mu(LIO) + 1/3 mu(IO) + 1/3 mu(O) = .8/3 + .4/3 = 0.4
  //   B: sorted I 0 <= L 1 = O 1:      0 mu(LIO) + 1 mu(LO)                = 0.6
  //   C: sorted O 0 <= L 1/2 <= I 1:   0 + 1/2 mu(LI) + 1/2 mu(I)          = .45 + .2 = 0.65
  // -> C.
  Situation s(kCorridor, 1.5, 1.0);
  ASSERT_EQ(s.clusters.size(), 3U);
  Mcdm mcdm{McdmParams{}};
  const auto c = mcdm.evaluate(s.observe());
  ASSERT_EQ(c.size(), 3U);
  const std::vector<Cell> cells = {{1, 2}, {9, 2}, {10, 2}};
  const std::vector<std::array<double, 3>> raw = {{5, 3, 6}, {3, 2, 7}, {4, 5, 4}};
  const std::vector<std::array<double, 3>> u = {{0, 1.0 / 3, 2.0 / 3}, {1, 0, 1}, {0.5, 1, 0}};
  const std::vector<double> global = {0.4, 0.6, 0.65};
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(c[k].cell, cells[k]);
    EXPECT_DOUBLE_EQ(c[k].length_m, raw[k][0]);
    EXPECT_DOUBLE_EQ(c[k].gain_m2, raw[k][1]);
    EXPECT_DOUBLE_EQ(c[k].overlap_m2, raw[k][2]);
    for (std::size_t j = 0; j < 3; ++j) EXPECT_NEAR(c[k].utility[j], u[k][j], 1e-12) << k << " " << j;
    EXPECT_NEAR(c[k].global, global[k], 1e-12) << k;
  }
  EXPECT_EQ(mcdm.decide(s.observe()).goal, (Cell{10, 2}));
}

TEST(Mcdm, AdditiveMeasureIsTheWeightedAverage) {
  // mu(L) .5, mu(I) .25, mu(O) .25 and sums for pairs: the weighted average
  //   A: .25/3 + .25 * 2/3 = .25   B: .5 + .25 = .75   C: .25 + .25 = .5   -> B
  Situation s(kCorridor, 1.5, 1.0);
  Mcdm mcdm(mcdm_params().read(
      {{"measure", {{"L", 0.5}, {"I", 0.25}, {"O", 0.25}, {"LI", 0.75}, {"LO", 0.75}, {"IO", 0.5}}}}, "p"));
  const auto c = mcdm.evaluate(s.observe());
  ASSERT_EQ(c.size(), 3U);
  EXPECT_NEAR(c[0].global, 0.25, 1e-12);
  EXPECT_NEAR(c[1].global, 0.75, 1e-12);
  EXPECT_NEAR(c[2].global, 0.5, 1e-12);
  EXPECT_EQ(mcdm.decide(s.observe()).goal, (Cell{9, 2}));
}

TEST(Mcdm, EqualCriterionAndSingleCandidateGetUtilityOne) {
  // Whole clusters: representatives (1,2) and (9,2). Make (1,2) unreachable: one candidate,
  // every utility 1, global mu(LIO) = 1.
  Situation s(kCorridor, 1.5);
  s.oracle.unreachable = {s.at(1, 2)};
  Mcdm mcdm{McdmParams{}};
  const auto c = mcdm.evaluate(s.observe());
  ASSERT_EQ(c.size(), 1U);
  EXPECT_EQ(c[0].cell, (Cell{9, 2}));
  EXPECT_EQ(c[0].utility, (std::array<double, 3>{1, 1, 1}));
  EXPECT_DOUBLE_EQ(c[0].global, 1.0);
  EXPECT_EQ(mcdm.decide(s.observe()).goal, (Cell{9, 2}));
  s.oracle.unreachable.insert(s.at(9, 2));
  EXPECT_EQ(mcdm.decide(s.observe()).kind, Decision::Kind::Finish);
}

TEST(Mcdm, ParamsAreValidatedWithPathAndPair) {
  EXPECT_EQ(configure_strategy("mcdm", nullptr).params,
            (nlohmann::json{
                {"measure", {{"L", 0.2}, {"I", 0.4}, {"O", 0.4}, {"LI", 0.9}, {"LO", 0.6}, {"IO", 0.8}}}}));
  const nlohmann::json good = {{"L", 0.2}, {"I", 0.4}, {"O", 0.4}, {"LI", 0.9}, {"LO", 0.6}, {"IO", 0.8}};
  EXPECT_NO_THROW((void)mcdm_params().read({{"measure", good}}, "p"));
  const auto error = [](const nlohmann::json& params) -> std::string {
    try {
      (void)make_strategy("mcdm", params, 1, "strategy");
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "";
  };
  // Not monotone: mu(L) = 0.7 > mu(LI) = 0.5 and mu(I) = 0.4 ok, mu(L) = 0.7 > mu(LO) = 0.6.
  nlohmann::json bad = good;
  bad["L"] = 0.7;
  bad["LI"] = 0.5;
  std::string what = error({{"measure", bad}});
  EXPECT_NE(what.find("strategy/params/measure: LI: mu(L) = 0.7 > mu(LI) = 0.5"), std::string::npos) << what;
  EXPECT_NE(what.find("; LO: mu(L) = 0.7 > mu(LO) = 0.6"), std::string::npos) << what;
  EXPECT_EQ(what.find("measure/IO"), std::string::npos) << what;
  // Out of range, missing, unknown subset, wrong type.
  bad = good;
  bad["O"] = 1.5;
  what = error({{"measure", bad}});
  EXPECT_NE(what.find("strategy/params/measure: O: value 1.5"), std::string::npos) << what;
  EXPECT_NE(what.find("[0, 1]"), std::string::npos) << what;
  bad = good;
  bad.erase("IO");
  what = error({{"measure", bad}});
  EXPECT_NE(what.find("strategy/params/measure: IO: missing"), std::string::npos) << what;
  bad = good;
  bad["LIO"] = 1.0;
  EXPECT_NE(error({{"measure", bad}}).find("strategy/params/measure"), std::string::npos);
  EXPECT_NE(error({{"measure", 3}}), "");
  EXPECT_NE(error({{"weights", good}}).find("strategy/params"), std::string::npos);
}

// ---------------------------------------------------------------- random_frontier

TEST(RandomFrontier, PicksTheDrawnReachableRepresentative) {
  // Single-cell clusters (1,2) (9,2) (10,2); (9,2) unreachable: candidates (1,2), (10,2), and
  // the choice is position uniform_below(2) of the generator (stream "random_frontier").
  Situation s(kCorridor, 1.5, 1.0);
  s.oracle.unreachable = {s.at(9, 2)};
  RandomFrontier rf(42);
  Rng rng = make_rng(42, "random_frontier");
  const std::vector<Cell> reachable = {{1, 2}, {10, 2}};
  for (int k = 0; k < 20; ++k) {
    EXPECT_EQ(rf.decide(s.observe()).goal, reachable[static_cast<std::size_t>(uniform_below(rng, 2))]);
  }
}

TEST(RandomFrontier, IsRoughlyUniform) {
  // 3000 decisions over 3 candidates: 1000 expected each; sd = sqrt(3000 * 1/3 * 2/3) = 26,
  // so +-130 is five standard deviations (and the seed is fixed).
  Situation s(kCorridor, 1.5, 1.0);
  RandomFrontier rf(3);
  std::map<int, int> count;
  for (int k = 0; k < 3000; ++k) ++count[rf.decide(s.observe()).goal.x];
  EXPECT_EQ(count.size(), 3U);
  for (const auto& [x, n] : count) EXPECT_NEAR(n, 1000, 130) << "x " << x;
}

TEST(RandomFrontier, CloneCopiesTheGeneratorAndNothingReachableFinishes) {
  Situation s(kCorridor, 1.5, 1.0);
  RandomFrontier rf(9);
  (void)rf.decide(s.observe());
  auto clone = rf.clone();
  EXPECT_TRUE(rf == dynamic_cast<const RandomFrontier&>(*clone));
  for (int k = 0; k < 10; ++k) EXPECT_EQ(rf.decide(s.observe()).goal, clone->decide(s.observe()).goal);
  EXPECT_FALSE(rf == RandomFrontier(10));
  for (int x = 0; x < 12; ++x) s.oracle.unreachable.insert(s.at(x, 2));
  EXPECT_EQ(rf.decide(s.observe()).kind, Decision::Kind::Finish);
  EXPECT_THROW((void)make_strategy("random_frontier", {{"p", 1}}, 1, "strategy"), ConfigError);
  EXPECT_EQ(configure_strategy("random_frontier", nullptr).params, nlohmann::json::object());
}

// ---------------------------------------------------------------- every strategy x planner

TEST(StrategyConformance, RegisteredCloneableAndNamed) {
  Situation s(kCorridor, 1.5);
  for (const std::string& name : strategy_names()) {
    auto a = make_strategy(name, nullptr, 3, "strategy");
    EXPECT_EQ(a->name(), name);
    auto b = a->clone();
    EXPECT_EQ(b->name(), name);
    const Decision da = a->decide(s.observe());
    const Decision db = b->decide(s.observe());
    EXPECT_EQ(da.kind, db.kind) << name;
    EXPECT_EQ(da.goal, db.goal) << name;
    (void)configure_strategy(name, nullptr);
  }
  for (const char* name : {"gbl", "mcdm", "random_frontier"}) {
    const auto names = strategy_names();
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  }
}

TEST(StrategyConformance, TheLinearScoredTraitIsWhatTheStrategiesAre) {
  // The registry's declaration and the made strategies agree, for each registered strategy and its
  // clone; the weight search's strategies are among them.
  int linear = 0;
  for (const std::string& name : strategy_names()) {
    const auto s = make_strategy(name, nullptr, 3, "strategy");
    const bool declared = strategy_traits(name).linear_scored;
    EXPECT_EQ(s->linear_scored() != nullptr, declared) << name;
    EXPECT_EQ(s->clone()->linear_scored() != nullptr, declared) << name;
    const Strategy& as_const = *s;
    EXPECT_EQ(as_const.linear_scored() != nullptr, declared) << name;
    linear += declared ? 1 : 0;
  }
  for (const char* name : {"energy_aware", "closest_frontier", "target_seeking"})
    EXPECT_TRUE(strategy_traits(name).linear_scored) << name;
  EXPECT_FALSE(strategy_traits("gbl").linear_scored);
  EXPECT_EQ(linear, 3);
}

TEST(StrategyConformance, EveryStrategyWithEveryPlannerCompletesSmallMaps) {
  for (const char* spec_text : {"rooms:w=24,h=18,door=3,seed=4", "random:w=24,h=24,p=0.2,seed=3"}) {
    const auto map = std::make_shared<const WorldMap>(load_map_spec(spec_text));
    for (const std::string& strategy : strategy_names()) {
      for (const std::string& planner : planner_names()) {
        // OMPL's anytime planners spend their whole time budget on every decision; RRTConnect
        // (it stops at its first path) stands for the OMPL planners here.
        if (planner.rfind("ompl:", 0) == 0 && planner != "ompl:RRTConnect") continue;
        RunSpec spec;
        spec.map = map;
        spec.strategy = configure_strategy(strategy, nullptr);
        spec.planner = configure_planner(planner, nullptr);
        spec.robot.sensor.range_m = 5.0;
        spec.seed = 2;
        const RunResult r = simulate(spec);
        EXPECT_EQ(r.end, EndReason::Complete)
            << spec_text << " " << strategy << " + " << planner << ": " << r.end_detail;
        EXPECT_DOUBLE_EQ(r.metrics.coverage, 1.0) << spec_text << " " << strategy << " + " << planner;
        EXPECT_GT(r.metrics.decisions, 1) << spec_text << " " << strategy << " + " << planner;
      }
    }
  }
}

TEST(HolzExploration, McdmWithAllWeightOnTravelIsClosestFrontier) {
  // mu(A) = 1 when L is in A, else 0: the Choquet integral is u_L, maximal exactly at the
  // shortest path (ties: the lowest cluster), closest_frontier's rule over the same candidates.
  RunSpec spec;
  spec.map = std::make_shared<const WorldMap>(load_map_spec("office:w=60,h=40,seed=3"));
  spec.robot.sensor.range_m = 6.0;
  spec.seed = 4;
  const RunResult cf = simulate(spec);
  spec.strategy = configure_strategy(
      "mcdm", {{"measure", {{"L", 1}, {"I", 0}, {"O", 0}, {"LI", 1}, {"LO", 1}, {"IO", 0}}}});
  const RunResult mcdm = simulate(spec);
  EXPECT_EQ(mcdm.end, EndReason::Complete);
  EXPECT_EQ(mcdm.trajectory, cf.trajectory);
}

TEST(HolzExploration, NewStrategiesCompleteGeneratedMapsAndAreDeterministic) {
  for (const char* strategy : {"gbl", "mcdm", "random_frontier"}) {
    for (const char* map : {"office:w=60,h=40,seed=1", "rooms:w=50,h=40,door=3,seed=5"}) {
      RunSpec spec;
      spec.map = std::make_shared<const WorldMap>(load_map_spec(map));
      spec.strategy = configure_strategy(strategy, nullptr);
      spec.robot.sensor.range_m = 6.0;
      spec.seed = 11;
      const RunResult a = simulate(spec);
      EXPECT_EQ(a.end, EndReason::Complete) << strategy << " " << map << " " << a.end_detail;
      EXPECT_DOUBLE_EQ(a.metrics.coverage, 1.0) << strategy << " " << map;
      const RunResult b = simulate(spec);
      EXPECT_EQ(a.trajectory, b.trajectory) << strategy << " " << map;
    }
  }
  // A 180 degree field of view works too (gain scans use the direction from the robot).
  RunSpec spec;
  spec.map = std::make_shared<const WorldMap>(load_map_spec("rooms:w=40,h=30,door=3,seed=2"));
  spec.robot.sensor.range_m = 6.0;
  spec.robot.sensor.fov_deg = 180.0;
  for (const char* strategy : {"gbl", "mcdm"}) {
    spec.strategy = configure_strategy(strategy, nullptr);
    const RunResult r = simulate(spec);
    EXPECT_EQ(r.end, EndReason::Complete) << strategy << " " << r.end_detail;
    EXPECT_DOUBLE_EQ(r.metrics.coverage, 1.0) << strategy;
  }
}

}  // namespace test_holz_strategies
}  // namespace fsweep
