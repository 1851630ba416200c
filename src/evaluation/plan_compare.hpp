#pragma once
/// @file plan_compare.hpp
/// Pair-by-pair comparison of planners on random queries, after Mei et al. 2006 section V-B
/// (shortest paths vs energy-efficient paths over > 3800 source/destination pairs on a random
/// map). The library part of `fsweep plan-compare` (src/cli/plan_compare_command.cpp):
/// drawing the pairs, planning them, and the statistics; no printing or files here.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "planners/planner.hpp"
#include "world/energy_model.hpp"
#include "world/grid.hpp"
#include "world/known_map.hpp"

namespace fsweep {
inline namespace evaluation {

/// One query of a comparison: every planner plans source -> target from `start_heading`.
struct ComparePair {
  Cell source;
  Cell target;
  /// 0..7 (grid.hpp headings).
  int start_heading = 0;
};

/// How to draw the pairs.
struct PairDrawOptions {
  /// Number of pairs (>= 1).
  int count = 4000;
  /// Run seed; the pairs come from stream "plan_compare.pairs" and the random start headings
  /// from stream "plan_compare.headings", so a fixed heading leaves the pairs unchanged.
  std::uint64_t seed = 1;
  /// Fixed start heading (0..7), or nullopt for a uniformly drawn heading per pair.
  std::optional<int> start_heading;
  /// The move rule used for reachability (src/search/octile_grid.hpp).
  bool allow_corner_cutting = false;
};

/// Draws `options.count` pairs of distinct known-free cells that are reachable from each other
/// (8-connected move rule), source and target each uniform over the free cells, rejecting
/// unreachable pairs and repeats: no two pairs have the same unordered {source, target}.
/// Deterministic for a seed. Throws ConfigError (at "--pairs"/"--start-heading") when count < 1,
/// a fixed heading is outside 0..7, or the map has fewer such unordered pairs than `count`
/// (e.g. fewer than 2 free cells in any connected region).
[[nodiscard]] std::vector<ComparePair> draw_compare_pairs(const KnownMap& known,
                                                          const PairDrawOptions& options);

/// What one planner returned for one pair (the PlanResult without the path).
struct PairPlan {
  PlanStatus status = PlanStatus::NoPath;
  double length_m = 0.0;
  double energy = 0.0;
  int stops = 0;
  int turns = 0;
  long expansions = 0;
  double time_s = 0.0;
};

/// Plans every pair with every planner (same request: the pair, its start heading, `energy`,
/// `allow_corner_cutting`, seed 0). Result [planner][pair]. Planners are used in order and keep
/// their state between queries.
[[nodiscard]] std::vector<std::vector<PairPlan>> plan_compare_pairs(
    const KnownMap& known, const std::vector<ComparePair>& pairs,
    const std::vector<std::unique_ptr<Planner>>& planners, const EnergyModel& energy,
    bool allow_corner_cutting);

/// Mean and Hyndman-Fan type 7 quantiles of a sample (all NaN for an empty sample).
struct SampleSummary {
  double mean = 0.0;
  double q05 = 0.0;
  double q25 = 0.0;
  double median = 0.0;
  double q75 = 0.0;
  double q95 = 0.0;
};

/// Summary of `values` (any order).
[[nodiscard]] SampleSummary summarize_sample(std::vector<double> values);

/// Planner `candidate` (j) against planner `baseline` (i), over the pairs both solved.
struct PlannerContrast {
  int baseline = 0;
  int candidate = 1;
  /// Pairs solved by both (the statistics below use only these).
  int pairs_used = 0;
  /// Per pair 100 (E_i - E_j) / E_i: positive when the candidate saves energy. Pairs with
  /// E_i == 0 (none when source != target and travel costs energy) are skipped.
  SampleSummary energy_saving_pct;
  /// Per pair 100 (L_j - L_i) / L_i: positive when the candidate is longer.
  SampleSummary length_increase_pct;
  /// 100 (sum E_i - sum E_j) / sum E_i over the used pairs.
  double total_energy_saving_pct = 0.0;
  /// 100 (sum L_j - sum L_i) / sum L_i over the used pairs.
  double total_length_increase_pct = 0.0;
  /// Shares (0..1) of used pairs where E_j < E_i, E_j == E_i, E_j > E_i; "equal" means within
  /// kEnergyEqualRel relative to E_i (rounding only: distinct energies differ by far more).
  double share_cheaper = 0.0;
  double share_equal = 0.0;
  double share_dearer = 0.0;
};

/// Relative tolerance of "equal energy" in PlannerContrast.
inline constexpr double kEnergyEqualRel = 1e-9;

/// Per-planner means over its solved pairs.
struct PlannerTotals {
  int solved = 0;
  double mean_length_m = 0.0;
  double mean_energy = 0.0;
  double mean_stops = 0.0;
  double mean_turns = 0.0;
  double mean_expansions = 0.0;
  /// Mean wall time per query (seconds).
  double mean_time_s = 0.0;
};

/// The statistics of a comparison.
struct CompareSummary {
  /// One per planner, in input order.
  std::vector<PlannerTotals> totals;
  /// One per planner pair (i < j), ordered by i then j.
  std::vector<PlannerContrast> contrasts;
};

/// Statistics of plans [planner][pair] (every planner the same number of pairs).
[[nodiscard]] CompareSummary summarize_comparison(const std::vector<std::vector<PairPlan>>& plans);

/// One line describing the baseline tie-breaking, for outputs: which shortest path `dijkstra`
/// and `astar` return among equal-length ones (BestFirstSearch's open-list order).
[[nodiscard]] std::string baseline_tie_breaking_note();

}  // namespace evaluation
}  // namespace fsweep
