// The energy-aware choice with a bounded search from the robot (EnergyAware::decide) against the
// full computation (candidates() and argmin_linear), on the engine's own distance oracle.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "core/random.hpp"
#include "sim/dock_field.hpp"
#include "sim/grid_distance_oracle.hpp"
#include "strategies/energy_aware.hpp"
#include "world/frontiers.hpp"
#include "world/known_map.hpp"

namespace fsweep {
namespace test_energy_aware_choice {  // not anonymous: unity builds put it beside other test files' helpers

constexpr double kInf = std::numeric_limits<double>::infinity();

/// A random decision: a map partly known (blobs of known cells, a share `occupied` of them
/// occupied), its frontier clusters, robot, dock, where the robot came from, a battery and a dock
/// field brought up to date in two stages (as in a run).
struct RandomDecision {
  KnownMap known;
  FrontierMap frontiers;
  std::vector<FrontierCluster> clusters;
  DockField dock_field;
  Cell robot{};
  Cell dock{};
  Cell previous{};
  BatteryView battery;
  bool corner_cutting = false;
  SensorParams sensor;

  RandomDecision(std::uint64_t seed, double resolution_m, double occupied = 0.15)
      : known(48, 36, resolution_m) {
    Rng rng = make_rng(seed, "energy_aware_choice");
    corner_cutting = uniform_below(rng, 4) == 0;
    // Known blobs: discs around random centres, some of their cells occupied.
    std::vector<int> first;
    std::vector<int> second;
    for (int blob = 0; blob < 7; ++blob) {
      const int cx = static_cast<int>(uniform_below(rng, 48));
      const int cy = static_cast<int>(uniform_below(rng, 36));
      const int r = 4 + static_cast<int>(uniform_below(rng, 9));
      for (int y = cy - r; y <= cy + r; ++y) {
        for (int x = cx - r; x <= cx + r; ++x) {
          const Cell c{x, y};
          if (!known.in_bounds(c) || (x - cx) * (x - cx) + (y - cy) * (y - cy) > r * r) continue;
          if (known.reveal(known.index(c), uniform01(rng) < occupied))
            (blob < 4 ? first : second).push_back(known.index(c));
        }
      }
    }
    frontiers = FrontierMap(known);
    clusters = frontiers.clusters(known, 6.0 * resolution_m, corner_cutting);
    robot = free_cell(rng);
    dock = uniform_below(rng, 5) == 0 ? robot : free_cell(rng);
    previous = uniform_below(rng, 4) == 0 ? robot : free_cell(rng);
    dock_field.take_in(known, first, dock, corner_cutting);
    dock_field.take_in(known, second, dock, corner_cutting);
    // As in a run after its first decision that asked: the field is built (its work is not the
    // decision's).
    if (dock_field.ready()) (void)dock_field.bring_up_to_date(known);
    // Battery: unlimited, or a reach between a quarter and twice the map's diagonal, above or
    // below half charge.
    if (uniform_below(rng, 3) != 0) {
      battery.capacity = 100.0;
      battery.level = 20.0 + 70.0 * uniform01(rng);
      battery.remaining_range_m = (15.0 + 105.0 * uniform01(rng)) * resolution_m;
    }
  }

  Cell free_cell(Rng& rng) const {
    for (;;) {
      const int i = static_cast<int>(uniform_below(rng, static_cast<std::uint64_t>(known.size())));
      if (known.is_free(i)) return known.cell(i);
    }
  }

  /// The decision's observation, with distances from `oracle`.
  [[nodiscard]] Observation observe(DistanceOracle& oracle) const {
    return Observation{known, frontiers, clusters,     oracle, sensor,  robot,
                       0,     previous,  std::nullopt, dock,   battery, 1};
  }
};

/// Integer weights in [0, 30] (ties happen often), some of them zero, and the special vectors.
std::array<double, 4> random_weights(Rng& rng, int round) {
  if (round == 0) return {1, 0, 0, 0};
  if (round == 1) return {0, 1, 0, 0};
  if (round == 2) return {10, 0, 9, 20};
  std::array<double, 4> w{};
  for (double& x : w) x = uniform_below(rng, 3) == 0 ? 0.0 : static_cast<double>(uniform_below(rng, 31));
  return w;
}

/// The energy-aware strategy with weights w (path distances) and cost unit `unit`.
EnergyAware energy_aware(const std::array<double, 4>& w, const std::string& unit = "m") {
  EnergyAwareParams p;
  p.w1 = w[0];
  p.w2 = w[1];
  p.w3 = w[2];
  p.w4 = w[3];
  p.unit = unit;
  return EnergyAware("energy_aware", p);
}

/// The cost unit of a seed's decisions: cells for even seeds (on the 0.05 m maps of seeds 6,
/// 12, ..., distances in cells are 20 times their metres), metres for odd ones.
std::string unit_of(std::uint64_t seed) { return seed % 2 == 0 ? "cell" : "m"; }

TEST(EnergyAwareChoice, BoundedSearchChoosesExactlyTheFullArgmin) {
  int decisions = 0;
  int goto_decisions = 0;
  long bounded_work = 0;  // cells settled; a failed probe can cost one decision more than the full search
  long full_work = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    RandomDecision d(seed, seed % 3 == 0 ? 0.05 : 1.0);
    Rng rng = make_rng(seed, "weights");
    for (int round = 0; round < 8; ++round) {
      const std::array<double, 4> w = random_weights(rng, round);
      EnergyAware ea = energy_aware(w, unit_of(seed));
      DistanceScratch scratch;
      // The full computation, on its own dock field copy (a DockField is a value).
      DockField full_dock = d.dock_field;
      GridDistanceOracle full_oracle(d.known, d.robot, d.dock, d.corner_cutting, &full_dock, scratch);
      const Candidates c = ea.candidates(d.observe(full_oracle));
      const int best = argmin_linear(c, ea.weights());
      DockField dock = d.dock_field;
      GridDistanceOracle oracle(d.known, d.robot, d.dock, d.corner_cutting, &dock, scratch);
      const Decision decision = ea.decide(d.observe(oracle));
      ++decisions;
      if (best < 0) {
        EXPECT_NE(decision.kind, Decision::Kind::GoTo) << "seed " << seed << " round " << round;
        continue;
      }
      ++goto_decisions;
      ASSERT_EQ(decision.kind, Decision::Kind::GoTo) << "seed " << seed << " round " << round;
      EXPECT_EQ(decision.goal, c.cells[static_cast<std::size_t>(best)])
          << "seed " << seed << " round " << round;
      bounded_work += oracle.expansions();
      full_work += full_oracle.expansions();
    }
  }
  EXPECT_EQ(decisions, 320);
  EXPECT_GT(goto_decisions, 200);  // most situations have a candidate: the test compares choices
  EXPECT_LT(bounded_work, full_work / 2);
}

/// A decision's candidates() by `reference` (weighing every term) and candidates_within(bounds)
/// by `ea`, each on its own oracle, with the work of each.
struct KeptAndAll {
  Candidates all;
  Candidates kept;
  long full_work = 0;
  long within_work = 0;
};
KeptAndAll kept_and_all(RandomDecision& d, EnergyAware& ea, EnergyAware& reference,
                        const WeightBounds& bounds) {
  KeptAndAll out;
  DistanceScratch scratch;
  DockField full_dock = d.dock_field;
  GridDistanceOracle full_oracle(d.known, d.robot, d.dock, d.corner_cutting, &full_dock, scratch);
  out.all = reference.candidates(d.observe(full_oracle));
  out.full_work = full_oracle.expansions();
  DockField dock = d.dock_field;
  GridDistanceOracle oracle(d.known, d.robot, d.dock, d.corner_cutting, &dock, scratch);
  out.kept = ea.candidates_within(d.observe(oracle), bounds);
  out.within_work = oracle.expansions();
  return out;
}

/// argmin_linear over `kept` chooses the cell argmin_linear over `all` chooses at `w`.
::testing::AssertionResult same_choice(const Candidates& all, const Candidates& kept,
                                       const std::array<double, 4>& w) {
  const int a = argmin_linear(all, w);
  const int b = argmin_linear(kept, w);
  if (b >= 0 && all.cells[static_cast<std::size_t>(a)] == kept.cells[static_cast<std::size_t>(b)]) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << "another choice at w (" << w[0] << ", " << w[1] << ", " << w[2] << ", " << w[3] << ")";
}

TEST(EnergyAwareChoice, CandidatesWithinABoxChooseAsAllCandidatesAtEveryVectorOfIt) {
  // candidates_within(lo, hi) may leave candidates out, but at every weight vector of the box
  // argmin_linear over what it keeps chooses the cell argmin_linear over candidates() chooses
  // (the exact weight search relies on it), and it does less work on narrow boxes.
  int compared = 0;
  int left_out = 0;
  long within_work = 0;
  long full_work = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    RandomDecision d(seed, seed % 3 == 0 ? 0.05 : 1.0);
    Rng rng = make_rng(seed, "boxes");
    for (int round = 0; round < 10; ++round) {
      // Boxes of every width, some touching w = 0 (where d_g may not matter at all).
      std::array<double, 4> lo{};
      std::array<double, 4> hi{};
      for (std::size_t k = 0; k < 4; ++k) {
        lo[k] = static_cast<double>(uniform_below(rng, 25));
        hi[k] = lo[k] + static_cast<double>(uniform_below(rng, round < 6 ? 6 : 30));
        if (uniform_below(rng, 4) == 0) lo[k] = 0.0;
      }
      // The strategy's own weights must not matter: with (1, 0, 0, 0) and no battery limit its
      // own decisions need no dock distances, but the box's vectors may weigh them. The
      // reference's own weights weigh every term, so its candidates() have every feature.
      EnergyAware ea = energy_aware(
          round % 2 == 0 ? std::array<double, 4>{10, 0, 9, 20} : std::array<double, 4>{1, 0, 0, 0},
          unit_of(seed));
      EnergyAware reference = energy_aware({1, 1, 1, 1}, unit_of(seed));
      const KeptAndAll c = kept_and_all(d, ea, reference, WeightBounds{lo, hi, {}});
      const Candidates& all = c.all;
      const Candidates& kept = c.kept;
      ASSERT_EQ(all.cells.empty(), kept.cells.empty()) << "seed " << seed << " round " << round;
      left_out += static_cast<int>(all.cells.size() - kept.cells.size());
      within_work += c.within_work;
      full_work += c.full_work;
      if (all.cells.empty()) continue;
      // Every integer vector of a box of at most 4,096, else its corners and 400 samples.
      std::uint64_t size = 1;
      for (std::size_t k = 0; k < 4; ++k) size *= static_cast<std::uint64_t>(hi[k] - lo[k]) + 1;
      const bool every = size <= 4096;
      for (std::uint64_t sample = 0; sample < (every ? size : 416); ++sample) {
        std::array<double, 4> w{};
        std::uint64_t rest = sample;
        for (std::size_t k = 0; k < 4; ++k) {
          const auto span = static_cast<std::uint64_t>(hi[k] - lo[k]) + 1;
          std::uint64_t offset = rest % span;
          if (!every) offset = sample < 16 ? ((sample >> k) & 1) * (span - 1) : uniform_below(rng, span);
          rest /= span;
          w[k] = lo[k] + static_cast<double>(offset);
        }
        ASSERT_TRUE(same_choice(all, kept, w)) << "seed " << seed << " round " << round;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 100000);
  EXPECT_GT(left_out, 100);  // narrow boxes do leave candidates out
  EXPECT_LT(within_work, full_work);
}

/// A narrow cone of weight vectors, as the exact weight search's regions are: the directions
/// within `width` of a random ray's (w1 > 0, so that d_g counts), the integer vectors of
/// [0, 30]^4 in them, and their bounding box.
struct NarrowCone {
  WeightDirections directions;
  std::vector<std::array<double, 4>> vectors;
  std::array<double, 4> lo{30, 30, 30, 30};
  std::array<double, 4> hi{};

  [[nodiscard]] WeightBounds bounds() const { return WeightBounds{lo, hi, directions}; }
};
NarrowCone random_cone(Rng& rng, double width) {
  std::array<double, 4> ray{};
  ray[0] = 1.0 + static_cast<double>(uniform_below(rng, 20));
  for (std::size_t k = 1; k < 4; ++k) ray[k] = static_cast<double>(uniform_below(rng, 21));
  const double sum = ray[0] + ray[1] + ray[2] + ray[3];
  NarrowCone out;
  WeightDirections& cone = out.directions;
  cone.zero = false;
  for (std::size_t k = 0; k < 4; ++k) {
    cone.lo[k] = std::max(0.0, ray[k] / sum - width);
    cone.hi[k] = std::min(1.0, ray[k] / sum + width);
  }
  for (int i = 0; i < 31 * 31 * 31 * 31; ++i) {
    const std::array<double, 4> w{double(i % 31), double(i / 31 % 31), double(i / 961 % 31),
                                  double(i / 29791)};
    const double s = w[0] + w[1] + w[2] + w[3];
    bool inside = s > 0.0;
    for (std::size_t k = 0; k < 4 && inside; ++k) inside = cone.lo[k] <= w[k] / s && w[k] / s <= cone.hi[k];
    if (!inside) continue;
    out.vectors.push_back(w);
    for (std::size_t k = 0; k < 4; ++k) {
      out.lo[k] = std::min(out.lo[k], w[k]);
      out.hi[k] = std::max(out.hi[k], w[k]);
    }
  }
  return out;
}

/// candidates_within(cone) with closest frontier's own weights, and candidates() of a reference
/// that weighs every term (so it has every feature), on decision `d` of seed `seed`.
KeptAndAll cone_candidates(RandomDecision& d, const NarrowCone& cone, std::uint64_t seed) {
  EnergyAware ea = energy_aware({1, 0, 0, 0}, unit_of(seed));
  EnergyAware reference = energy_aware({1, 1, 1, 1}, unit_of(seed));
  return kept_and_all(d, ea, reference, cone.bounds());
}

TEST(EnergyAwareChoice, CandidatesWithinNarrowDirectionsChooseAsAllCandidatesThere) {
  // The exact weight search's regions are narrow cones through the origin: a wide box, narrow
  // directions. candidates_within() may close representatives by the directions; at every
  // integer vector of [0, 30]^4 whose direction is in them, argmin_linear over what it keeps
  // chooses the cell argmin_linear over candidates() chooses.
  int compared = 0;
  int left_out = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    RandomDecision d(seed, seed % 3 == 0 ? 0.05 : 1.0);
    Rng rng = make_rng(seed, "cones");
    for (int round = 0; round < 6; ++round) {
      const NarrowCone cone = random_cone(rng, round < 3 ? 0.01 : 0.05);
      ASSERT_FALSE(cone.vectors.empty());
      const KeptAndAll c = cone_candidates(d, cone, seed);
      const Candidates& all = c.all;
      const Candidates& kept = c.kept;
      ASSERT_EQ(all.cells.empty(), kept.cells.empty()) << "seed " << seed << " round " << round;
      if (all.cells.empty()) continue;
      left_out += static_cast<int>(all.cells.size() - kept.cells.size());
      for (const std::array<double, 4>& w : cone.vectors) {
        ASSERT_TRUE(same_choice(all, kept, w)) << "seed " << seed << " round " << round;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 10000);
  EXPECT_GT(left_out, 1000);  // the directions close representatives (about 10x the box alone)
}

TEST(EnergyAwareChoice, CandidatesWithinOpenSpaceNeedNoSearchFromTheRobot) {
  // Known space without obstacles (the free-space weight search): most representatives have a
  // known free path of octile length, so candidates_within() measures them without a search
  // from the robot, in the order the proofs close the rest soonest. It chooses as all
  // candidates do at every vector of narrow cones, with a small part of the full search's work.
  int compared = 0;
  int searched = 0;
  int decisions = 0;
  long within_work = 0;
  long full_work = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    RandomDecision d(seed, seed % 3 == 0 ? 0.05 : 1.0, 0.0);
    Rng rng = make_rng(seed, "open cones");
    for (int round = 0; round < 4; ++round) {
      const NarrowCone cone = random_cone(rng, round < 2 ? 0.01 : 0.05);
      ASSERT_FALSE(cone.vectors.empty());
      const KeptAndAll c = cone_candidates(d, cone, seed);
      ASSERT_EQ(c.all.cells.empty(), c.kept.cells.empty()) << "seed " << seed << " round " << round;
      if (c.all.cells.empty()) continue;
      ++decisions;
      searched += c.within_work > 0 ? 1 : 0;
      within_work += c.within_work;
      full_work += c.full_work;
      for (const std::array<double, 4>& w : cone.vectors) {
        ASSERT_TRUE(same_choice(c.all, c.kept, w)) << "seed " << seed << " round " << round;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 10000);
  EXPECT_GT(decisions, 100);
  std::cout << "open space: " << searched << " of " << decisions
            << " decisions searched from the robot; work " << within_work << " of " << full_work << "\n";
  EXPECT_LT(searched, decisions / 2);
  EXPECT_LT(within_work, full_work / 4);
}

TEST(EnergyAwareChoice, LowerBoundsNeverExceedTheSearchedDistances) {
  int infinite_bounds = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    RandomDecision d(seed, seed % 2 == 0 ? 0.05 : 1.0);
    DistanceScratch scratch;
    GridDistanceOracle oracle(d.known, d.robot, d.dock, d.corner_cutting, &d.dock_field, scratch);
    std::vector<int> cells;
    for (int i = 0; i < d.known.size(); ++i) {
      if (d.known.is_free(i)) cells.push_back(i);
    }
    (void)oracle.from_dock(cells, kInf);  // brings the dock field up to date: the triangle bound applies
    const std::vector<double> exact = oracle.from_robot(cells, kInf);
    int finite_bounds = 0;
    const std::vector<double> bounds = oracle.lower_bounds_from_robot(cells);
    ASSERT_EQ(bounds.size(), cells.size());
    for (std::size_t k = 0; k < cells.size(); ++k) {
      const double bound = bounds[k];
      EXPECT_LE(bound, exact[k]) << "seed " << seed << " cell " << cells[k];
      ++(bound == kInf ? infinite_bounds : finite_bounds);
    }
    EXPECT_GT(finite_bounds, 0);
  }
  EXPECT_GT(infinite_bounds, 0);  // blobs the dock cannot reach, though the robot's blob can
}

TEST(EnergyAwareChoice, InOpenSpaceOnePointSearchSettlesTheChoice) {
  // A known free disc of radius 60 cells with the robot and the dock at its centre: every
  // frontier's octile bound is its exact length, so the first A* probe certifies the choice and
  // the decision settles a few hundred cells instead of the disc's 11,000.
  KnownMap known(161, 161, 1.0);
  std::vector<int> revealed;
  const Cell centre{80, 80};
  for (int i = 0; i < known.size(); ++i) {
    const Cell c = known.cell(i);
    if ((c.x - centre.x) * (c.x - centre.x) + (c.y - centre.y) * (c.y - centre.y) <= 60 * 60) {
      known.reveal(i, false);
      revealed.push_back(i);
    }
  }
  const FrontierMap frontiers(known);
  const std::vector<FrontierCluster> clusters = frontiers.clusters(known, 3.0, false);
  DockField dock;
  dock.take_in(known, revealed, centre, false);
  (void)dock.bring_up_to_date(known);  // built, as after a run's first decision
  for (const auto& w : {std::array<double, 4>{10, 0, 9, 20}, std::array<double, 4>{1, 0, 0, 0}}) {
    EnergyAware ea = energy_aware(w);
    BatteryView battery;
    battery.capacity = 1000.0;  // limited, so closest frontier takes the bounded path too
    battery.level = 1000.0;
    battery.remaining_range_m = 1000.0;
    SensorParams sensor;
    DistanceScratch scratch;
    const auto observe = [&](DistanceOracle& oracle) {
      return Observation{known, frontiers, clusters,     oracle, sensor,  centre,
                         0,     centre,    std::nullopt, centre, battery, 1};
    };
    DockField full_dock = dock;
    GridDistanceOracle full_oracle(known, centre, centre, false, &full_dock, scratch);
    const Candidates c = ea.candidates(observe(full_oracle));
    const int best = argmin_linear(c, ea.weights());
    ASSERT_GE(best, 0);
    DockField bounded_dock = dock;
    GridDistanceOracle oracle(known, centre, centre, false, &bounded_dock, scratch);
    const Decision d = ea.decide(observe(oracle));
    ASSERT_EQ(d.kind, Decision::Kind::GoTo);
    EXPECT_EQ(d.goal, c.cells[static_cast<std::size_t>(best)]);
    EXPECT_GT(full_oracle.expansions(), 10000);
    EXPECT_LT(oracle.expansions(), 500) << "w1 " << w[0];
  }
}

}  // namespace test_energy_aware_choice
}  // namespace fsweep
