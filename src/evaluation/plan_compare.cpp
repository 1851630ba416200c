#include "evaluation/plan_compare.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_set>
#include <utility>

#include "core/config_error.hpp"
#include "core/random.hpp"
#include "core/statistics.hpp"
#include "search/octile_grid.hpp"

namespace fsweep {
inline namespace evaluation {
namespace {

/// Connected regions of the known-free cells under the move rule.
struct Regions {
  /// Region id of every cell (-1 for cells that are not known free).
  std::vector<int> label;
  /// Number of cells of each region.
  std::vector<long> size;
};

/// Breadth-first flood fill. The move rule is symmetric, so "same label" is "reachable".
Regions free_regions(const KnownMap& known, bool allow_corner_cutting) {
  Regions r;
  r.label.assign(static_cast<std::size_t>(known.size()), -1);
  std::vector<int> queue;
  for (int seed = 0; seed < known.size(); ++seed) {
    if (!known.is_free(seed) || r.label[static_cast<std::size_t>(seed)] >= 0) continue;
    const int id = static_cast<int>(r.size.size());
    queue.assign(1, seed);
    r.label[static_cast<std::size_t>(seed)] = id;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      for_each_octile_neighbour(known, queue[head], allow_corner_cutting, [&](int next, double /*cost*/) {
        auto& l = r.label[static_cast<std::size_t>(next)];
        if (l >= 0) return;
        l = id;
        queue.push_back(next);
      });
    }
    r.size.push_back(static_cast<long>(queue.size()));
  }
  return r;
}

}  // namespace

std::vector<ComparePair> draw_compare_pairs(const KnownMap& known, const PairDrawOptions& options) {
  if (options.count < 1) {
    throw ConfigError("--pairs", "must be >= 1, got " + std::to_string(options.count));
  }
  if (options.start_heading && (*options.start_heading < 0 || *options.start_heading > 7)) {
    throw ConfigError("--start-heading",
                      "must be 'random' or 0..7, got " + std::to_string(*options.start_heading));
  }

  // 1. Free cells and their connected regions; the number of distinct reachable pairs.
  const Regions regions = free_regions(known, options.allow_corner_cutting);
  const std::vector<int>& label = regions.label;
  std::vector<int> free_cells;
  for (int i = 0; i < known.size(); ++i) {
    if (known.is_free(i)) free_cells.push_back(i);
  }
  long double available = 0;
  for (const long n : regions.size) {
    available += static_cast<long double>(n) * static_cast<long double>(n - 1) / 2;
  }
  if (static_cast<long double>(options.count) > available) {
    throw ConfigError("--pairs", "the map has " + std::to_string(free_cells.size()) +
                                     " free cells and only " +
                                     std::to_string(static_cast<long long>(available)) +
                                     " distinct reachable pairs; asked for " + std::to_string(options.count));
  }

  // 2. Rejection sampling: uniform source and target, kept if distinct, reachable and new.
  Rng pair_rng = make_rng(options.seed, "plan_compare.pairs");
  Rng heading_rng = make_rng(options.seed, "plan_compare.headings");
  const auto n_free = static_cast<std::uint64_t>(free_cells.size());
  const auto n_cells = static_cast<std::uint64_t>(known.size());
  std::unordered_set<std::uint64_t> used;
  std::vector<ComparePair> pairs;
  pairs.reserve(static_cast<std::size_t>(options.count));
  // Generous cap so a nearly exhausted pair set cannot loop forever (coupon-collector tail).
  const long long max_attempts = 1000LL * options.count + 10'000'000LL;
  for (long long attempt = 0; std::cmp_less(pairs.size(), options.count); ++attempt) {
    if (attempt >= max_attempts) {
      throw ConfigError("--pairs",
                        "could not draw " + std::to_string(options.count) +
                            " distinct reachable pairs; use fewer pairs or a map with more free cells");
    }
    const int s = free_cells[static_cast<std::size_t>(uniform_below(pair_rng, n_free))];
    const int t = free_cells[static_cast<std::size_t>(uniform_below(pair_rng, n_free))];
    if (s == t || label[static_cast<std::size_t>(s)] != label[static_cast<std::size_t>(t)]) continue;
    const auto lo = static_cast<std::uint64_t>(std::min(s, t));
    const auto hi = static_cast<std::uint64_t>(std::max(s, t));
    if (!used.insert(lo * n_cells + hi).second) continue;
    const int heading =
        options.start_heading ? *options.start_heading : static_cast<int>(uniform_below(heading_rng, 8));
    pairs.push_back(ComparePair{known.cell(s), known.cell(t), heading});
  }
  return pairs;
}

std::vector<std::vector<PairPlan>> plan_compare_pairs(const KnownMap& known,
                                                      const std::vector<ComparePair>& pairs,
                                                      const std::vector<std::unique_ptr<Planner>>& planners,
                                                      const EnergyModel& energy, bool allow_corner_cutting) {
  std::vector<std::vector<PairPlan>> plans(planners.size());
  for (std::size_t p = 0; p < planners.size(); ++p) {
    plans[p].reserve(pairs.size());
    for (const ComparePair& pair : pairs) {
      PlanRequest request;
      request.start = pair.source;
      request.goal = pair.target;
      request.start_heading = pair.start_heading;
      request.energy = energy;
      request.allow_corner_cutting = allow_corner_cutting;
      const PlanResult r = planners[p]->plan(known, request);
      plans[p].push_back(PairPlan{r.status, r.length_m, r.energy, r.stops, r.turns, r.expansions, r.time_s});
    }
  }
  return plans;
}

SampleSummary summarize_sample(std::vector<double> values) {
  if (values.empty()) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, nan, nan, nan, nan};
  }
  std::sort(values.begin(), values.end());
  const double mean = std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
  return {mean,
          quantile_sorted(values, 0.05),
          quantile_sorted(values, 0.25),
          quantile_sorted(values, 0.5),
          quantile_sorted(values, 0.75),
          quantile_sorted(values, 0.95)};
}

CompareSummary summarize_comparison(const std::vector<std::vector<PairPlan>>& plans) {
  CompareSummary summary;
  const std::size_t n_pairs = plans.empty() ? 0 : plans.front().size();

  // 1. Per planner: means over its solved pairs.
  for (const auto& runs : plans) {
    PlannerTotals t;
    for (const PairPlan& r : runs) {
      if (r.status != PlanStatus::Success) continue;
      ++t.solved;
      t.mean_length_m += r.length_m;
      t.mean_energy += r.energy;
      t.mean_stops += r.stops;
      t.mean_turns += r.turns;
      t.mean_expansions += static_cast<double>(r.expansions);
      t.mean_time_s += r.time_s;
    }
    if (t.solved > 0) {
      const auto n = static_cast<double>(t.solved);
      t.mean_length_m /= n;
      t.mean_energy /= n;
      t.mean_stops /= n;
      t.mean_turns /= n;
      t.mean_expansions /= n;
      t.mean_time_s /= n;
    }
    summary.totals.push_back(t);
  }

  // 2. Per planner pair (i < j): per-pair savings, ratio of totals, shares.
  for (std::size_t i = 0; i < plans.size(); ++i) {
    for (std::size_t j = i + 1; j < plans.size(); ++j) {
      PlannerContrast c;
      c.baseline = static_cast<int>(i);
      c.candidate = static_cast<int>(j);
      std::vector<double> saving;
      std::vector<double> increase;
      double sum_ei = 0.0;
      double sum_ej = 0.0;
      double sum_li = 0.0;
      double sum_lj = 0.0;
      int cheaper = 0;
      int equal = 0;
      int dearer = 0;
      for (std::size_t k = 0; k < n_pairs; ++k) {
        const PairPlan& a = plans[i][k];
        const PairPlan& b = plans[j][k];
        if (a.status != PlanStatus::Success || b.status != PlanStatus::Success) continue;
        ++c.pairs_used;
        sum_ei += a.energy;
        sum_ej += b.energy;
        sum_li += a.length_m;
        sum_lj += b.length_m;
        if (a.energy > 0.0) saving.push_back(100.0 * (a.energy - b.energy) / a.energy);
        if (a.length_m > 0.0) increase.push_back(100.0 * (b.length_m - a.length_m) / a.length_m);
        const double tol = kEnergyEqualRel * std::max(1.0, std::abs(a.energy));
        if (b.energy < a.energy - tol) {
          ++cheaper;
        } else if (b.energy > a.energy + tol) {
          ++dearer;
        } else {
          ++equal;
        }
      }
      c.energy_saving_pct = summarize_sample(std::move(saving));
      c.length_increase_pct = summarize_sample(std::move(increase));
      const double nan = std::numeric_limits<double>::quiet_NaN();
      c.total_energy_saving_pct = sum_ei > 0.0 ? 100.0 * (sum_ei - sum_ej) / sum_ei : nan;
      c.total_length_increase_pct = sum_li > 0.0 ? 100.0 * (sum_lj - sum_li) / sum_li : nan;
      if (c.pairs_used > 0) {
        const auto n = static_cast<double>(c.pairs_used);
        c.share_cheaper = cheaper / n;
        c.share_equal = equal / n;
        c.share_dearer = dearer / n;
      }
      summary.contrasts.push_back(c);
    }
  }
  return summary;
}

std::string baseline_tie_breaking_note() {
  return "dijkstra/astar tie-breaking among equal-length paths: the open list pops smaller f = g + h first, "
         "then larger g, then smaller cell index (y * width + x); a cell keeps the first parent that reached "
         "it "
         "with its final g (BestFirstSearch, src/search/grid_search.hpp). shortest_fewest_turns is the "
         "cheapest "
         "of all shortest paths.";
}

}  // namespace evaluation
}  // namespace fsweep
