// The exact weight search against brute force: for every weight vector of small grids, the
// behaviour the search attributes to it is the run simulate() gives for that vector alone (end
// reason and every field of the result but the effort metrics), the behaviours' vector counts
// add up to the grid, and the result is the same for any thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "sim/effort_free.hpp"
#include "sim/heuristics.hpp"
#include "sim/simulation.hpp"
#include "strategies/registry.hpp"
#include "weightsearch/exact_search.hpp"
#include "world/map_spec.hpp"

namespace fsweep {
namespace {

using nlohmann::json;
using Point = std::array<int, WeightGrid::kMaxWeights>;

/// An energy-aware run on `map` whose choices depend on all four weights: a battery (d_gbe
/// changes sign at half charge, eq. 9) and a short sensor (many decisions).
RunSpec spec_on(const std::string& map, double battery, const json& heuristics = json::array()) {
  RunSpec s;
  s.map = std::make_shared<const WorldMap>(load_map_spec(map));
  s.strategy = configure_strategy("energy_aware", nullptr);
  s.heuristics = heuristics_from_json(heuristics, "heuristics");
  s.robot.sensor.range_m = 3.0;
  s.robot.battery_capacity = battery;
  s.seed = 5;
  return s;
}

using test::without_effort;

/// The behaviours of `spec` over `grid`, in order of their choices.
std::vector<Behaviour> behaviours_of(const RunSpec& spec, const WeightGrid& grid, int threads,
                                     ExactSearchStats* stats = nullptr) {
  std::vector<Behaviour> found;
  const ExactSearchStats s = exact_search(std::span<const RunSpec>(&spec, 1), grid, threads,
                                          [&](Behaviour&& b) { found.push_back(std::move(b)); });
  if (stats != nullptr) *stats = s;
  std::sort(found.begin(), found.end(),
            [](const Behaviour& a, const Behaviour& b) { return a.choices < b.choices; });
  return found;
}

/// `spec` with the energy-aware weights `w`.
RunSpec with_weights(RunSpec spec, const std::vector<double>& w) {
  spec.strategy =
      configure_strategy("energy_aware", json{{"w1", w[0]}, {"w2", w[1]}, {"w3", w[2]}, {"w4", w[3]}});
  return spec;
}

/// Every point of `grid` is in exactly one behaviour, whose result is the brute-force run's.
void expect_agrees_with_brute_force(const RunSpec& spec, const WeightGrid& grid, const std::string& what) {
  const std::vector<Behaviour> behaviours = behaviours_of(spec, grid, 2);
  // Weights that never change a choice would test nothing.
  ASSERT_GE(behaviours.size(), 5U) << what;
  std::cout << what << ": " << behaviours.size() << " behaviours of " << grid.size() << " vectors\n";
  std::uint64_t total = 0;
  for (const Behaviour& b : behaviours) {
    total += b.vectors;
    EXPECT_EQ(b.vectors, grid.count(b.region)) << what;
    EXPECT_TRUE(grid.contains(b.region, b.representative)) << what;
  }
  EXPECT_EQ(total, grid.size()) << what;
  std::map<Point, std::size_t> owner;
  for (std::size_t i = 0; i < behaviours.size(); ++i) {
    grid.for_each_point(behaviours[i].region, [&](const Point& at) {
      EXPECT_TRUE(owner.emplace(at, i).second) << what << ": a point in two behaviours";
    });
  }
  ASSERT_EQ(owner.size(), grid.size()) << what;
  for (const auto& [at, i] : owner) {
    const Behaviour& b = behaviours[i];
    // The representative is the smallest point, and the bounds hold every point.
    EXPECT_LE(b.representative, at) << what;
    for (std::size_t k = 0; k < WeightGrid::kMaxWeights; ++k) {
      EXPECT_LE(b.bounds[k][0], at[k]) << what;
      EXPECT_GE(b.bounds[k][1], at[k]) << what;
    }
    const std::vector<double> w = grid.weights_at(at);
    const RunResult alone = without_effort(simulate(with_weights(spec, w)));
    const RunResult shared = without_effort(b.results.at(0));
    ASSERT_EQ(alone.end, shared.end) << what << " at (" << w[0] << ", " << w[1] << ", " << w[2] << ", "
                                     << w[3] << ")";
    ASSERT_TRUE(alone == shared) << what << " at (" << w[0] << ", " << w[1] << ", " << w[2] << ", " << w[3]
                                 << "): distance " << alone.metrics.distance_m << " alone, "
                                 << shared.metrics.distance_m << " shared";
  }
}

std::vector<double> integers(int from, int to, int step = 1) {
  std::vector<double> v;
  for (int i = from; i <= to; i += step) v.push_back(i);
  return v;
}

// Long (label long: make test-long, the nightly job); the shorter boxes below run in make test.
TEST(ExactSearchLong, DISABLED_EveryVectorOfASmallBoxBehavesAsItsRunAlone) {
  const RunSpec spec = spec_on("office:w=32,h=32,seed=3", 120.0);
  // Small enough for the sanitizer pass (-O0), which runs every vector's simulation too.
  const WeightGrid grid({integers(0, 4), integers(0, 4), integers(0, 4), integers(0, 4)});
  expect_agrees_with_brute_force(spec, grid, "office [0,4]^4");
}

TEST(ExactSearch, ScaledCopiesBoundariesAndTheZeroVectorBehaveAsTheirRunsAlone) {
  // Steps and offsets that put points on the boundaries of decisions between candidates
  // (scaled copies of one direction, e.g. (10, 0, 9, 20) and (20, 0, 18, 40)), the zero vector
  // (every cost 0: the lowest candidate), and blocks cut at the grid's end (sizes not
  // multiples of 8).
  const RunSpec spec = spec_on("rooms:w=22,h=22,seed=4", 90.0, json({"rr"}));
  const WeightGrid grid({{0, 10, 20, 30}, {0, 1}, {0, 9, 18, 27}, integers(0, 40, 4)});
  expect_agrees_with_brute_force(spec, grid, "rooms scaled");
}

TEST(ExactSearch, TheSpecsOwnWeightsDoNotMatterEvenWithoutABattery) {
  // With an unlimited battery the strategy skips the dock distances when its own w2 and w3 are
  // 0; the search must still give the vectors with w2 or w3 > 0 their real d_gb.
  RunSpec spec = spec_on("office:w=32,h=32,seed=3", std::numeric_limits<double>::infinity());
  spec.strategy = configure_strategy("energy_aware", json{{"w1", 1}, {"w2", 0}, {"w3", 0}, {"w4", 0}});
  const WeightGrid grid({{1, 2}, {0, 3, 7}, {0, 5}, {0, 4, 9}});
  expect_agrees_with_brute_force(spec, grid, "office, unlimited battery");
}

// Long (label long: make test-long, the nightly job).
TEST(ExactSearchLong, DISABLED_IsTheSameForAnyThreadCount) {
  const RunSpec spec = spec_on("office:w=32,h=32,seed=3", 120.0);
  const WeightGrid grid({integers(0, 20, 4), integers(0, 20, 5), integers(0, 20, 4), integers(0, 20, 5)});
  ExactSearchStats one_stats;
  ExactSearchStats two_stats;
  const std::vector<Behaviour> one = behaviours_of(spec, grid, 1, &one_stats);
  const std::vector<Behaviour> two = behaviours_of(spec, grid, 2, &two_stats);
  ASSERT_EQ(one.size(), two.size());
  EXPECT_GT(one.size(), 1U) << "weights that never matter test nothing";
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].choices, two[i].choices);
    EXPECT_EQ(one[i].vectors, two[i].vectors);
    EXPECT_EQ(one[i].representative, two[i].representative);
    EXPECT_TRUE(without_effort(one[i].results.at(0)) == without_effort(two[i].results.at(0)));
  }
  EXPECT_EQ(one_stats.splits, two_stats.splits);
  EXPECT_EQ(one_stats.forks + 1, one.size());
}

// Long (label long: make test-long, the nightly job).
TEST(ExactSearchLong, DISABLED_AClassIsSearchedJointlyAsTheCommonRefinementOfItsInstances) {
  // Two maps searched together: two vectors share a joint behaviour exactly when they share a
  // behaviour on each map alone, and the joint behaviour's run on each map is that behaviour's.
  const std::vector<RunSpec> instances{spec_on("office:w=32,h=32,seed=3", 120.0),
                                       spec_on("rooms:w=28,h=24,seed=7", 90.0)};
  const WeightGrid grid({integers(0, 3), integers(0, 3), integers(0, 3), integers(0, 3)});
  std::vector<std::map<Point, std::size_t>> alone_owner(instances.size());
  std::vector<std::vector<Behaviour>> alone(instances.size());
  for (std::size_t i = 0; i < instances.size(); ++i) {
    alone[i] = behaviours_of(instances[i], grid, 1);
    for (std::size_t b = 0; b < alone[i].size(); ++b) {
      grid.for_each_point(alone[i][b].region, [&](const Point& at) { alone_owner[i][at] = b; });
    }
  }
  std::vector<Behaviour> joint;
  (void)exact_search(instances, grid, 2, [&](Behaviour&& b) { joint.push_back(std::move(b)); });
  // Every pair of per-map behaviours that some vector combines is one joint behaviour.
  std::map<std::pair<std::size_t, std::size_t>, int> combos;
  for (const auto& [at, b0] : alone_owner[0]) ++combos[{b0, alone_owner[1].at(at)}];
  ASSERT_GT(alone[0].size() + alone[1].size(), 6U) << "weights that change nothing test nothing";
  ASSERT_EQ(joint.size(), combos.size());
  std::uint64_t total = 0;
  for (const Behaviour& b : joint) {
    total += b.vectors;
    ASSERT_EQ(b.results.size(), 2U);
    std::set<std::pair<std::size_t, std::size_t>> owners;
    grid.for_each_point(b.region, [&](const Point& at) {
      owners.insert({alone_owner[0].at(at), alone_owner[1].at(at)});
    });
    ASSERT_EQ(owners.size(), 1U) << "a joint behaviour mixes per-map behaviours";
    const auto [b0, b1] = *owners.begin();
    EXPECT_EQ(static_cast<int>(b.vectors), combos.at({b0, b1}));
    EXPECT_TRUE(without_effort(b.results[0]) == without_effort(alone[0][b0].results.at(0)));
    EXPECT_TRUE(without_effort(b.results[1]) == without_effort(alone[1][b1].results.at(0)));
  }
  EXPECT_EQ(total, grid.size());
}

TEST(ExactSearch, WhatARegionDoesAlikeOnEveryInstanceIsSimulatedOnce) {
  // A class of one map twice: its second instance decides as the first, so each split of the
  // first finds the second at the same decision, and the joint search takes twice the steps of
  // the map's search alone; it does not run the second instance again from its start for each
  // share of a split of the first.
  const RunSpec spec = spec_on("office:w=32,h=32,seed=3", 120.0);
  const WeightGrid grid({integers(0, 2), integers(0, 2), integers(0, 2), integers(0, 2)});
  ExactSearchStats alone;
  const std::vector<Behaviour> once = behaviours_of(spec, grid, 1, &alone);
  ASSERT_GE(alone.splits, 3U) << "a search without splits tests nothing";
  const std::vector<RunSpec> twice{spec, spec};
  std::vector<Behaviour> joint;
  const ExactSearchStats both =
      exact_search(twice, grid, 1, [&](Behaviour&& b) { joint.push_back(std::move(b)); });
  EXPECT_EQ(joint.size(), once.size());
  EXPECT_EQ(both.splits, alone.splits);
  EXPECT_EQ(both.steps, 2 * alone.steps);
}

TEST(ExactSearch, ShardsFindPartsOfTheWholeSearchsBehavioursWithTheirTraces) {
  // The whole grid's behaviours have distinct traces; a shard's behaviours are their parts in
  // the shard (same trace, same run), and the parts of one trace join into the whole region.
  const RunSpec spec = spec_on("office:w=32,h=32,seed=3", 120.0);
  const WeightGrid grid({integers(0, 3), integers(0, 2), integers(0, 9), integers(0, 2)});
  const std::vector<Behaviour> whole = behaviours_of(spec, grid, 2);
  ASSERT_GE(whole.size(), 5U);
  std::map<std::uint64_t, std::size_t> by_trace;
  for (std::size_t i = 0; i < whole.size(); ++i) {
    EXPECT_TRUE(by_trace.emplace(whole[i].trace, i).second) << "two behaviours with one trace";
  }
  std::map<std::uint64_t, std::uint64_t> joined;
  std::size_t parts = 0;
  for (std::uint64_t i = 0; i < 3; ++i) {
    const WeightRegion shard = grid.shard(i, 3);
    (void)exact_search(
        std::span<const RunSpec>(&spec, 1), grid, 2,
        [&](Behaviour&& b) {
          ++parts;
          const Behaviour& w = whole.at(by_trace.at(b.trace));
          EXPECT_TRUE(grid.contains(w.region, b.representative));
          EXPECT_TRUE(without_effort(b.results.at(0)) == without_effort(w.results.at(0)));
          joined[b.trace] += b.vectors;
        },
        nullptr, &shard);
  }
  EXPECT_GT(parts, whole.size()) << "no behaviour spans two shards: the join is untested";
  for (const Behaviour& b : whole) EXPECT_EQ(joined[b.trace], b.vectors);
}

/// Branch and bound on the distance to final coverage of one run.
BranchAndBound distance_bnb() {
  BranchAndBound bnb;
  bnb.objective = [](const std::vector<RunResult>& r) {
    return r.at(0).metrics.distance_to_final_coverage_m;
  };
  bnb.lower_bound = [](std::span<const Simulation> sims) {
    return sims.front().metrics_so_far().distance_to_final_coverage_m;
  };
  return bnb;
}

/// distance_bnb() resumed with `incumbent`, adding to `resolved` the vectors of the regions it
/// prunes (from any thread) and of the leaves it finds beaten (its behaviours' the caller adds).
BranchAndBound resumed_bnb(double incumbent, std::atomic<std::uint64_t>& resolved) {
  BranchAndBound bnb = distance_bnb();
  bnb.incumbent = incumbent;
  bnb.on_pruned = [&resolved](std::uint64_t v) { resolved += v; };
  bnb.on_leaf = [&resolved](const CertifiedLeaf& l) {
    if (l.kind == CertifiedLeaf::Kind::Beaten) resolved += l.vectors;
  };
  return bnb;
}

TEST(ExactSearch, AnIncumbentPrunesEverythingWorseFromTheStart) {
  // Branch and bound started with the optimum as its incumbent (a resumed search) reports only
  // optimal behaviours, and the same ones as a search without it.
  const RunSpec spec = spec_on("office:w=32,h=32,seed=3", 120.0);
  const WeightGrid grid({integers(0, 3), integers(0, 2), integers(0, 5), integers(0, 2)});
  BranchAndBound bnb = distance_bnb();
  const auto search = [&](double incumbent, std::vector<double>& objectives) {
    bnb.incumbent = incumbent;
    return exact_search(
        std::span<const RunSpec>(&spec, 1), grid, 2,
        [&](Behaviour&& b) { objectives.push_back(b.results.at(0).metrics.distance_to_final_coverage_m); },
        &bnb);
  };
  std::vector<double> first;
  const ExactSearchStats cold = search(std::numeric_limits<double>::infinity(), first);
  ASSERT_GE(first.size(), 2U) << "a search that finds the optimum first tests no incumbent";
  std::vector<double> warm_found;
  const ExactSearchStats warm = search(cold.best, warm_found);
  EXPECT_EQ(warm.best, cold.best);
  ASSERT_FALSE(warm_found.empty());
  for (const double o : warm_found) EXPECT_EQ(o, cold.best);
  EXPECT_EQ(warm_found.size(), static_cast<std::size_t>(std::count(first.begin(), first.end(), cold.best)));
  EXPECT_LT(warm.behaviours, cold.behaviours);

  // Probes: the optimal vector run alone first is as good an incumbent.
  std::vector<double> probed_found;
  bnb.incumbent = std::numeric_limits<double>::infinity();
  std::array<int, WeightGrid::kMaxWeights> optimal{};
  (void)exact_search(
      std::span<const RunSpec>(&spec, 1), grid, 1,
      [&](Behaviour&& b) {
        if (b.results.at(0).metrics.distance_to_final_coverage_m == cold.best) optimal = b.representative;
      },
      &bnb);
  bnb.probes = {optimal};
  std::vector<double> probed;
  const ExactSearchStats with_probe = exact_search(
      std::span<const RunSpec>(&spec, 1), grid, 2,
      [&](Behaviour&& b) { probed.push_back(b.results.at(0).metrics.distance_to_final_coverage_m); }, &bnb);
  EXPECT_EQ(with_probe.probes, 1U);
  EXPECT_EQ(with_probe.best_probe, cold.best);
  EXPECT_EQ(probed.size(), warm_found.size());
  for (const double o : probed) EXPECT_EQ(o, cold.best);
  const std::vector<std::array<int, WeightGrid::kMaxWeights>> spread =
      spread_probes(grid, grid.everything(), 16, 7);
  EXPECT_EQ(spread.size(), 16U);
  EXPECT_EQ(spread, spread_probes(grid, grid.everything(), 16, 7)) << "not a pure function";
  for (const auto& p : spread) EXPECT_TRUE(grid.contains(grid.everything(), p));
}

TEST(ExactSearch, BothOrdersFindTheSameOptimalBehaviours) {
  // Smallest bound first (anytime) explores the tree in another order than depth first, with
  // few waiting branches allowed (so it also drains by the largest bound): the optimal
  // behaviours it reports are the same, for any thread count.
  const RunSpec spec = spec_on("office:w=32,h=32,seed=3", 120.0);
  const WeightGrid grid({integers(0, 3), integers(0, 2), integers(0, 5), integers(0, 2)});
  const auto optimal = [&](SearchOrder order, std::size_t max_open, int threads) {
    BranchAndBound bnb = distance_bnb();
    bnb.order = order;
    bnb.max_open = max_open;
    std::vector<std::pair<std::vector<int>, double>> found;
    const ExactSearchStats stats = exact_search(
        std::span<const RunSpec>(&spec, 1), grid, threads,
        [&](Behaviour&& b) {
          found.emplace_back(b.choices, b.results.at(0).metrics.distance_to_final_coverage_m);
        },
        &bnb);
    std::erase_if(found, [&](const auto& f) { return f.second != stats.best; });
    std::sort(found.begin(), found.end());
    EXPECT_EQ(stats.unresolved_bound, std::numeric_limits<double>::infinity())
        << "a finished search left a branch open";
    EXPECT_EQ(stats.unresolved_branches, 0U);
    return found;
  };
  const auto depth = optimal(SearchOrder::Depth, kDefaultMaxOpenBranches, 2);
  ASSERT_FALSE(depth.empty());
  EXPECT_EQ(optimal(SearchOrder::Bound, kDefaultMaxOpenBranches, 1), depth);
  EXPECT_EQ(optimal(SearchOrder::Bound, 2, 2), depth);
}

TEST(ExactSearch, TheAnytimeBoundNeverPassesTheOptimumAndRisesToIt) {
  // Every anytime state brackets the optimum (lower <= optimum <= best), in both orders; a
  // stopped search's unresolved bound is a lower bound of the optimum too.
  const RunSpec spec = spec_on("office:w=32,h=32,seed=3", 120.0);
  const WeightGrid grid({integers(0, 3), integers(0, 2), integers(0, 5), integers(0, 2)});
  double optimum = 0.0;
  {
    BranchAndBound bnb = distance_bnb();
    optimum = exact_search(
                  std::span<const RunSpec>(&spec, 1), grid, 2, [](Behaviour&&) {}, &bnb)
                  .best;
  }
  for (const SearchOrder order : {SearchOrder::Depth, SearchOrder::Bound}) {
    BranchAndBound bnb = distance_bnb();
    bnb.order = order;
    bnb.anytime_interval_s = 0.0;  // every change
    std::vector<AnytimeState> states;
    bnb.on_anytime = [&](const AnytimeState& s) { states.push_back(s); };
    (void)exact_search(
        std::span<const RunSpec>(&spec, 1), grid, 2, [](Behaviour&&) {}, &bnb);
    ASSERT_GE(states.size(), 10U);
    double best = std::numeric_limits<double>::infinity();
    for (const AnytimeState& s : states) {
      EXPECT_LE(s.lower, optimum);
      EXPECT_GE(s.best, optimum);
      EXPECT_LE(s.best, best) << "the best objective rose";
      best = s.best;
    }
    EXPECT_GT(states.back().lower, states.front().lower);
    // Stopped halfway: the bound over what is left is below the optimum.
    std::atomic<bool> stop{false};
    BranchAndBound stopping = distance_bnb();
    stopping.order = order;
    int reported = 0;
    const ExactSearchStats stopped = exact_search(
        std::span<const RunSpec>(&spec, 1), grid, 2,
        [&](Behaviour&&) {
          if (++reported == 2) stop.store(true);
        },
        &stopping, nullptr, nullptr, &stop);
    ASSERT_TRUE(stopped.stopped);
    EXPECT_GT(stopped.unresolved_branches, 0U);
    EXPECT_LE(stopped.unresolved_bound, optimum);
    EXPECT_GE(stopped.best, optimum);
  }
}

/// Journals behaviour `b` of the search of `root` as a finished leaf in `done`.
void journal_leaf(std::unordered_map<std::uint64_t, SubtreeTally>& done, std::uint64_t root,
                  const Behaviour& b) {
  SubtreeTally leaf;
  leaf.vectors = b.vectors;
  leaf.behaviours = 1;
  done.emplace(subtree_of(root, b.choices), leaf);
}

/// A resume from the finished subtrees `done`, counting the vectors it skips.
struct Resume {
  explicit Resume(const std::unordered_map<std::uint64_t, SubtreeTally>& done) {
    journal.done = &done;
    journal.on_skipped = [this](std::uint64_t /*id*/, std::uint64_t v) { skipped += v; };  // any thread
  }
  Resume(const Resume&) = delete;
  Resume& operator=(const Resume&) = delete;
  SubtreeJournal journal;
  std::atomic<std::uint64_t> skipped{0};
};

TEST(ExactSearch, SkippingFinishedSubtreesResumesWithTheRestOfTheBehaviours) {
  // A whole search journals its finished subtrees (nodes that split) and behaviours (leaves).
  // A rerun given some of them, as a killed search leaves them, skips those subtrees whole:
  // what it reports and what it skipped make up the whole search, each vector once.
  const RunSpec spec = spec_on("office:w=32,h=32,seed=3", 120.0);
  const WeightGrid grid({integers(0, 3), integers(0, 2), integers(0, 5), integers(0, 2)});
  const std::uint64_t root = subtree_root(grid.everything());
  std::vector<Behaviour> whole;
  std::vector<std::pair<std::uint64_t, SubtreeTally>> nodes;  // in the order they finished
  SubtreeJournal recording;
  recording.on_done = [&](std::uint64_t id, const SubtreeTally& t) { nodes.emplace_back(id, t); };
  const ExactSearchStats full = exact_search(
      std::span<const RunSpec>(&spec, 1), grid, 2, [&](Behaviour&& b) { whole.push_back(std::move(b)); },
      nullptr, nullptr, &recording);
  ASSERT_GE(nodes.size(), 4U);
  ASSERT_EQ(nodes.back().first, root) << "the root finishes last";
  EXPECT_EQ(nodes.back().second.vectors, grid.size());
  EXPECT_EQ(nodes.back().second.behaviours, whole.size());
  std::map<std::uint64_t, const Behaviour*> by_trace;
  for (const Behaviour& b : whole) by_trace[b.trace] = &b;

  for (const std::size_t kept : {std::size_t{0}, nodes.size() / 3, nodes.size() - 1, nodes.size()}) {
    // The first `kept` nodes to finish, and the behaviours of every other third.
    std::unordered_map<std::uint64_t, SubtreeTally> done(nodes.begin(),
                                                         nodes.begin() + static_cast<std::ptrdiff_t>(kept));
    for (std::size_t i = 0; i < whole.size(); i += 3) journal_leaf(done, root, whole[i]);
    Resume resume(done);
    const std::atomic<std::uint64_t>& skipped = resume.skipped;
    std::uint64_t reported = 0;
    std::set<std::uint64_t> seen;
    const ExactSearchStats again = exact_search(
        std::span<const RunSpec>(&spec, 1), grid, 2,
        [&](Behaviour&& b) {
          reported += b.vectors;
          EXPECT_TRUE(seen.insert(b.trace).second) << "a behaviour reported twice";
          const Behaviour& w = *by_trace.at(b.trace);
          EXPECT_EQ(b.vectors, w.vectors);
          EXPECT_EQ(b.choices, w.choices);
          EXPECT_EQ(subtree_of(root, b.choices), subtree_of(root, w.choices));
          EXPECT_FALSE(done.contains(subtree_of(root, b.choices))) << "a journaled behaviour found again";
        },
        nullptr, nullptr, &resume.journal);
    EXPECT_EQ(reported + skipped, grid.size()) << kept;
    EXPECT_EQ(again.behaviours, full.behaviours) << kept << ": journaled behaviours count as finished";
    if (kept == nodes.size()) {
      EXPECT_EQ(skipped.load(), grid.size());
      EXPECT_EQ(again.forks, 0U) << "the root is journaled: nothing to search";
    } else if (kept == 0) {
      EXPECT_GT(reported, 0U);
      EXPECT_EQ(again.forks, full.forks) << "leaves alone are skipped where they are forked";
    } else {
      EXPECT_LT(again.forks, full.forks) << kept;
    }
  }
}

TEST(ExactSearch, APrunedBranchNeverSwallowsAJournaledLeaf) {
  // A resumed branch and bound whose incumbent is already the optimum prunes higher in the tree
  // than the killed search did: a branch it would prune whole may hold leaves the journal has.
  // It must go on to their splits and skip them there, so that the journal's regions and the
  // rerun's partition the box, each vector once (a certificate counts them).
  const RunSpec spec = spec_on("office:w=32,h=32,seed=3", 120.0);
  const WeightGrid grid({integers(0, 3), integers(0, 2), integers(0, 5), integers(0, 2)});
  const std::uint64_t root = subtree_root(grid.everything());
  BranchAndBound bnb = distance_bnb();
  std::vector<std::pair<std::vector<int>, std::uint64_t>> leaves;  // pruned and beaten: path, vectors
  bnb.on_leaf = [&](const CertifiedLeaf& l) {
    leaves.emplace_back(std::vector<int>(l.choices.begin(), l.choices.end()), l.vectors);
  };
  // Reported: the behaviours no better one was known for when they finished (the first ones
  // are not optimal).
  const ExactSearchStats cold = exact_search(
      std::span<const RunSpec>(&spec, 1), grid, 1,
      [&](Behaviour&& b) { leaves.emplace_back(b.choices, b.vectors); }, &bnb);
  ASSERT_GE(leaves.size(), 10U);
  // Every other one journaled, as a killed search leaves them.
  std::unordered_map<std::uint64_t, SubtreeTally> done;
  std::vector<std::vector<int>> paths;
  std::uint64_t journaled = 0;
  for (std::size_t i = 0; i < leaves.size(); i += 2) {
    SubtreeTally t;
    t.vectors = leaves[i].second;
    journaled += t.vectors;
    done.emplace(subtree_of(root, leaves[i].first), t);
    paths.push_back(leaves[i].first);
  }
  const std::unordered_set<std::uint64_t> ancestors = journal_ancestors(root, paths);
  EXPECT_TRUE(ancestors.contains(root));
  EXPECT_FALSE(ancestors.contains(subtree_of(root, paths.front()))) << "a leaf is not its own ancestor";
  for (const bool guarded : {false, true}) {
    for (const int threads : {1, 2}) {
      Resume resume(done);
      if (guarded) resume.journal.ancestors = &ancestors;
      std::atomic<std::uint64_t> resolved{0};
      BranchAndBound warm = resumed_bnb(cold.best, resolved);
      const ExactSearchStats again = exact_search(
          std::span<const RunSpec>(&spec, 1), grid, threads, [&](Behaviour&& b) { resolved += b.vectors; },
          &warm, nullptr, &resume.journal);
      EXPECT_EQ(again.best, cold.best);
      // What the rerun resolves (and journals) besides the journal's leaves.
      if (guarded) {
        EXPECT_EQ(resume.skipped.load(), journaled) << threads << " threads";
        EXPECT_EQ(resolved + journaled, grid.size()) << threads << " threads";
      } else {
        // Unguarded, it does prune above journaled leaves (or this test would test nothing).
        EXPECT_LT(resume.skipped.load(), journaled) << threads << " threads";
        EXPECT_GT(resolved + journaled, grid.size()) << threads << " threads";
      }
    }
  }
}

TEST(ExactSearch, AResumedSearchSkipsEachTopmostJournaledSubtreeOnceSoWhatItResolvedCountsAtOnce) {
  // Branch and bound stopped partway journals its behaviours, pruned and beaten leaves (with
  // their paths) and finished nodes (ids). journal_topmost() finds the finished subtrees below
  // no other, whose vectors are all the stopped search resolved; the resumed search skips each
  // of them exactly once and resolves the rest, so a resume can count them from its start
  // (the runner's resolved_vectors) without the count ever falling back.
  const RunSpec spec = spec_on("office:w=32,h=32,seed=3", 120.0);
  const WeightGrid grid({integers(0, 3), integers(0, 2), integers(0, 5), integers(0, 2)});
  const std::uint64_t root = subtree_root(grid.everything());
  std::mutex mutex;  // on_skipped and on_pruned may come from two threads at once
  std::unordered_map<std::uint64_t, SubtreeTally> done;
  std::vector<std::vector<int>> paths;
  std::uint64_t resolved = 0;
  const auto leaf = [&](std::span<const int> choices, std::uint64_t vectors) {
    const std::lock_guard<std::mutex> lock(mutex);
    SubtreeTally t;
    t.vectors = vectors;
    done.emplace(subtree_of(root, choices), t);
    paths.emplace_back(choices.begin(), choices.end());
    resolved += vectors;
  };
  std::atomic<bool> stop{false};
  SubtreeJournal journal;
  std::size_t nodes = 0;
  journal.on_done = [&](std::uint64_t id, const SubtreeTally& t) {
    const std::lock_guard<std::mutex> lock(mutex);
    done.emplace(id, t);
    // Stopped once a few nodes that split have finished, so that some leaves lie below them.
    if (++nodes == 3) stop.store(true);
  };
  BranchAndBound first = distance_bnb();
  first.on_leaf = [&](const CertifiedLeaf& l) { leaf(l.choices, l.vectors); };
  // One thread: the same nodes finish first every time, so the stop comes at the same point.
  const ExactSearchStats stopped = exact_search(
      std::span<const RunSpec>(&spec, 1), grid, 1, [&](Behaviour&& b) { leaf(b.choices, b.vectors); }, &first,
      nullptr, &journal, &stop);
  ASSERT_TRUE(stopped.stopped) << "the search finished before the stop";
  ASSERT_GE(nodes, 3U);
  ASSERT_LT(resolved, grid.size());

  const JournalTop top = journal_topmost(root, paths, done);
  EXPECT_EQ(top.vectors, resolved) << "the topmost subtrees hold what the stopped search resolved";
  EXPECT_LT(top.ids.size(), paths.size()) << "no leaf lies below a finished node: the test tests little";
  const std::unordered_set<std::uint64_t> ancestors = journal_ancestors(root, paths);
  std::map<std::uint64_t, int> skipped;  // id -> times
  std::uint64_t skipped_vectors = 0;
  SubtreeJournal resume;
  resume.done = &done;
  resume.ancestors = &ancestors;
  resume.on_skipped = [&](std::uint64_t id, std::uint64_t v) {
    const std::lock_guard<std::mutex> lock(mutex);
    ++skipped[id];
    skipped_vectors += v;
  };
  std::atomic<std::uint64_t> resolved_again{0};
  BranchAndBound second = resumed_bnb(stopped.best, resolved_again);
  const ExactSearchStats rest = exact_search(
      std::span<const RunSpec>(&spec, 1), grid, 2, [&](Behaviour&& b) { resolved_again += b.vectors; },
      &second, nullptr, &resume);
  EXPECT_FALSE(rest.stopped);
  EXPECT_EQ(skipped.size(), top.ids.size());
  for (const auto& [id, times] : skipped) {
    EXPECT_TRUE(top.ids.contains(id)) << "skipped a subtree below another finished one";
    EXPECT_EQ(times, 1) << "skipped a subtree twice";
  }
  EXPECT_EQ(skipped_vectors, top.vectors);
  EXPECT_EQ(top.vectors + resolved_again, grid.size()) << "each vector resolved once";
}

TEST(ExactSearch, AStoppedSearchLeavesFinishedPartsOnlyAndResumesWithTheRest) {
  // The stop flag, set as the third behaviour is reported (as SIGINT sets it), ends the search
  // with part of the grid unresolved; what it reported and journaled is what the whole search
  // reports and journals there, and a rerun given that journal finds exactly the rest.
  const RunSpec spec = spec_on("office:w=32,h=32,seed=3", 120.0);
  const WeightGrid grid({integers(0, 3), integers(0, 2), integers(0, 5), integers(0, 2)});
  const std::uint64_t root = subtree_root(grid.everything());
  std::map<std::uint64_t, SubtreeTally> whole_nodes;
  SubtreeJournal recording;
  recording.on_done = [&](std::uint64_t id, const SubtreeTally& t) { whole_nodes.emplace(id, t); };
  std::map<std::uint64_t, std::uint64_t> whole;  // trace -> vectors
  const ExactSearchStats full = exact_search(
      std::span<const RunSpec>(&spec, 1), grid, 2, [&](Behaviour&& b) { whole.emplace(b.trace, b.vectors); },
      nullptr, nullptr, &recording);
  ASSERT_FALSE(full.stopped);
  ASSERT_GE(whole.size(), 10U);

  std::atomic<bool> stop{false};
  std::unordered_map<std::uint64_t, SubtreeTally> done;
  SubtreeJournal journal;
  journal.on_done = [&](std::uint64_t id, const SubtreeTally& t) { done.emplace(id, t); };
  std::vector<Behaviour> first;
  const ExactSearchStats stopped = exact_search(
      std::span<const RunSpec>(&spec, 1), grid, 2,
      [&](Behaviour&& b) {
        first.push_back(std::move(b));
        if (first.size() == 3) stop.store(true);
      },
      nullptr, nullptr, &journal, &stop);
  EXPECT_TRUE(stopped.stopped);
  EXPECT_LT(first.size(), whole.size()) << "the stop did not end the search early";
  EXPECT_FALSE(done.contains(root)) << "a stopped search finished its root";
  for (const Behaviour& b : first) EXPECT_EQ(whole.at(b.trace), b.vectors);
  for (const auto& [id, t] : done) {
    ASSERT_TRUE(whole_nodes.contains(id)) << "journaled a node the whole search never finished";
    EXPECT_EQ(t.vectors, whole_nodes.at(id).vectors);
    EXPECT_EQ(t.behaviours, whole_nodes.at(id).behaviours);
  }

  for (const Behaviour& b : first) journal_leaf(done, root, b);
  Resume resume(done);
  const std::atomic<std::uint64_t>& skipped = resume.skipped;
  std::uint64_t reported = 0;
  std::set<std::uint64_t> seen;
  for (const Behaviour& b : first) seen.insert(b.trace);
  const std::atomic<bool> never{false};
  const ExactSearchStats rest = exact_search(
      std::span<const RunSpec>(&spec, 1), grid, 2,
      [&](Behaviour&& b) {
        reported += b.vectors;
        EXPECT_TRUE(seen.insert(b.trace).second) << "a behaviour found twice";
        EXPECT_EQ(whole.at(b.trace), b.vectors);
      },
      nullptr, nullptr, &resume.journal, &never);
  EXPECT_FALSE(rest.stopped);
  EXPECT_EQ(reported + skipped, grid.size());
  EXPECT_EQ(seen.size(), whole.size());
  EXPECT_EQ(rest.behaviours, full.behaviours);

  // Stopped before it starts: nothing reported, nothing journaled.
  std::size_t any = 0;
  done.clear();
  const ExactSearchStats none = exact_search(
      std::span<const RunSpec>(&spec, 1), grid, 2, [&](Behaviour&&) { ++any; }, nullptr, nullptr, &journal,
      &stop);
  EXPECT_TRUE(none.stopped);
  EXPECT_EQ(any, 0U);
  EXPECT_TRUE(done.empty());
}

/// The message of the std::invalid_argument that exact_search throws for `spec` over `grid`.
std::string refusal(const RunSpec& spec, const WeightGrid& grid) {
  try {
    (void)behaviours_of(spec, grid, 1);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(ExactSearch, RefusesStrategiesAndGridsThatDoNotFit) {
  RunSpec spec = spec_on("office:w=32,h=32,seed=3", 120.0);
  const WeightGrid four({integers(0, 2), integers(0, 2), integers(0, 2), integers(0, 2)});
  EXPECT_EQ(refusal(spec, WeightGrid({integers(0, 2), integers(0, 2), integers(0, 2)})),
            "exact_search: strategy energy_aware has 4 weights, the grid 3");
  EXPECT_EQ(refusal(spec, WeightGrid({integers(0, 2), integers(0, 2), {0, 251}, integers(0, 2)})),
            "energy_aware: w3 = 251 is out of range; allowed: 0..250");
  spec.strategy = configure_strategy("random_frontier", nullptr);
  EXPECT_EQ(refusal(spec, four), "exact_search: strategy random_frontier is not linear-scored");
  const RunSpec office = spec_on("office:w=32,h=32,seed=3", 120.0);
  EXPECT_THROW((void)exact_search(std::span<const RunSpec>(&office, 1), four, 0, [](Behaviour&&) {}),
               std::invalid_argument);
  EXPECT_THROW((void)exact_search(std::span<const RunSpec>(), four, 1, [](Behaviour&&) {}),
               std::invalid_argument);
}

TEST(SimulationChoice, MisusesAreRefused) {
  // step_choosing without a choice(), or with a candidate it did not offer; the hooks on a
  // strategy that is not linear-scored.
  Simulation sim(spec_on("office:w=32,h=32,seed=3", 120.0));
  EXPECT_THROW((void)sim.step_choosing(0), std::logic_error);
  const std::array<double, 4> lo{0, 0, 0, 0};
  const std::array<double, 4> hi{250, 250, 250, 250};
  const Candidates* c = sim.choice(WeightBounds{lo, hi, {}});
  ASSERT_NE(c, nullptr);
  EXPECT_THROW((void)sim.step_choosing(static_cast<int>(c->cells.size())), std::logic_error);
  EXPECT_THROW(sim.set_weights(std::array<double, 4>{1, 2, 3, 300}), std::invalid_argument);
  EXPECT_THROW(sim.set_weights(std::array<double, 3>{1, 2, 3}), std::invalid_argument);
  RunSpec other = spec_on("office:w=32,h=32,seed=3", 120.0);
  other.strategy = configure_strategy("random_frontier", nullptr);
  Simulation random(other);
  EXPECT_EQ(random.choice(WeightBounds{lo, hi, {}}), nullptr);
  EXPECT_THROW(random.set_weights(std::array<double, 4>{1, 0, 0, 0}), std::logic_error);
}

}  // namespace
}  // namespace fsweep
