#include "optimum/lower_bound.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <numeric>

#include "core/random.hpp"
#include "search/octile_grid.hpp"

namespace fsweep {
inline namespace optimum {
namespace {

constexpr std::size_t kFarthestFirstCandidates = 4000;

/// The trip bound's spacings between witnesses' groups, as shares of the range per charge.
constexpr double kTripSpacings[] = {0.0, 1.0 / 64, 1.0 / 32, 1.0 / 16, 1.0 / 8, 1.0 / 4};

/// The explorable targets, fewest viewpoints first (then by id): the hardest to see first.
std::vector<int> explorable_by_fewest_viewpoints(const CoverageInstance& in) {
  std::vector<int> order;
  for (int t = 0; t < in.targets(); ++t) {
    if (in.is_explorable(t)) order.push_back(t);
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return in.seen_from.row(a).size() < in.seen_from.row(b).size(); });
  return order;
}

std::vector<int> group_cells(const CoverageInstance& in, int target) {
  std::vector<int> cells;
  for (const int n : in.seen_from.row(target)) cells.push_back(in.node_cell[static_cast<std::size_t>(n)]);
  return cells;
}

/// Hardest to see first: explorable targets by fewest viewpoints (then id), each taken when none
/// of its viewpoints is a viewpoint of a witness taken before.
std::vector<int> fewest_viewpoints_first(const CoverageInstance& in, int max_witnesses) {
  const std::vector<int> order = explorable_by_fewest_viewpoints(in);
  std::vector<std::uint8_t> taken(static_cast<std::size_t>(in.nodes()), 0);
  std::vector<int> out;
  for (const int t : order) {
    if (static_cast<int>(out.size()) >= max_witnesses) break;
    const auto from = in.seen_from.row(t);
    if (std::any_of(from.begin(), from.end(),
                    [&](int n) { return taken[static_cast<std::size_t>(n)] != 0; })) {
      continue;
    }
    for (const int n : from) taken[static_cast<std::size_t>(n)] = 1;
    out.push_back(t);
  }
  return out;
}

/// Farthest first: the explorable target whose group is farthest from the start and the groups
/// chosen so far (ties: fewer viewpoints, then id), disjoint from them, until none is farther
/// than 0.
std::vector<int> farthest_first(const CoverageInstance& in, int max_witnesses) {
  // Candidates: the kFarthestFirstCandidates targets with the fewest viewpoints (each step reads
  // every candidate's viewpoints: all targets' would cost the whole visibility table a step).
  std::vector<int> candidates = explorable_by_fewest_viewpoints(in);
  if (candidates.size() > kFarthestFirstCandidates) candidates.resize(kFarthestFirstCandidates);
  std::sort(candidates.begin(), candidates.end());
  const int start_cell = in.node_cell[static_cast<std::size_t>(in.start_node)];
  std::vector<double> near = node_distances_m(in, std::span<const int>(&start_cell, 1));
  std::vector<std::uint8_t> taken(static_cast<std::size_t>(in.nodes()), 0);
  std::vector<int> out;
  while (static_cast<int>(out.size()) < max_witnesses) {
    int best = -1;
    double best_d = 0.0;
    for (const int t : candidates) {
      const auto from = in.seen_from.row(t);
      double d = kInfinity;
      bool free = true;
      for (const int n : from) {
        if (taken[static_cast<std::size_t>(n)] != 0) {
          free = false;
          break;
        }
        d = std::min(d, near[static_cast<std::size_t>(n)]);
      }
      if (!free || d == kInfinity || d <= 0.0) continue;
      if (best < 0 || d > best_d || (d == best_d && from.size() < in.seen_from.row(best).size())) {
        best = t;
        best_d = d;
      }
    }
    if (best < 0) break;
    out.push_back(best);
    for (const int n : in.seen_from.row(best)) taken[static_cast<std::size_t>(n)] = 1;
    const std::vector<double> field = node_distances_m(in, group_cells(in, best));
    for (std::size_t n = 0; n < near.size(); ++n) near[n] = std::min(near[n], field[n]);
  }
  return out;
}

}  // namespace

double sweep_bound(const CoverageInstance& in) {
  if (in.start_node < 0 || in.dock_node < 0) return 0.0;
  // The reveal rate: the most targets one step reveals that the scan before it had not, per metre.
  double rate = 0.0;  // targets per metre
  double longest_step = 0.0;
  std::vector<int> fresh;
  for (int n = 0; n < in.nodes(); ++n) {
    const Cell a = in.cell_of_node(n);
    const auto before = in.sees.row(n);
    for (int h = 0; h < 8; ++h) {
      const Cell b{a.x + kDirections[static_cast<std::size_t>(h)].x,
                   a.y + kDirections[static_cast<std::size_t>(h)].y};
      const int m = in.node_at(b);
      if (m < 0 || !octile_step_allowed(in.truth, a, b, in.allow_corner_cutting)) continue;
      const auto after = in.sees.row(m);
      fresh.clear();
      std::set_difference(after.begin(), after.end(), before.begin(), before.end(),
                          std::back_inserter(fresh));
      const double length = step_length(h) * in.resolution_m;
      rate = std::max(rate, static_cast<double>(fresh.size()) / length);
      longest_step = std::max(longest_step, length);
    }
  }
  // Targets the start's scan leaves, by their groups' distance from the dock.
  const int dock_cell = in.node_cell[static_cast<std::size_t>(in.dock_node)];
  const std::vector<double> from_dock = node_distances_m(in, std::span<const int>(&dock_cell, 1));
  std::vector<std::uint8_t> seen_at_start(static_cast<std::size_t>(in.targets()), 0);
  for (const int t : in.sees.row(in.start_node)) seen_at_start[static_cast<std::size_t>(t)] = 1;
  std::vector<double> far;  // per target still to reveal: its group's distance from the dock
  for (int t = 0; t < in.targets(); ++t) {
    if (!in.is_explorable(t) || seen_at_start[static_cast<std::size_t>(t)] != 0) continue;
    double d = kInfinity;
    for (const int n : in.seen_from.row(t)) d = std::min(d, from_dock[static_cast<std::size_t>(n)]);
    far.push_back(d);
  }
  if (far.empty() || rate <= 0.0) return 0.0;
  std::sort(far.begin(), far.end(), std::greater<>());
  const double s = longest_step;
  const double delta = from_dock[static_cast<std::size_t>(in.start_node)];
  const double range = in.range_per_charge_m;
  double best = 0.0;
  for (std::size_t i = 0; i < far.size(); ++i) {
    if (i + 1 < far.size() && far[i + 1] == far[i]) continue;  // the last of equal distances
    const double rho = far[i];
    const double need = static_cast<double>(i + 1) / rate;  // metres of steps ending at >= rho
    const double first_overhead = std::max(0.0, rho - s - delta);
    int trips = 1;
    if (in.limited_battery()) {
      const double last_capacity = range - rho + s;
      const double first_capacity = range - 2.0 * rho + s + delta;
      const double middle_capacity = range - 2.0 * rho + s;
      if (need > last_capacity + delta) {  // more than one stretch, from the start, holds
        trips = 2;
        const double rest = need - last_capacity - std::max(0.0, first_capacity);
        if (rest > 0.0 && middle_capacity > 0.0) trips += static_cast<int>(std::ceil(rest / middle_capacity));
      }
    }
    double overhead = first_overhead;
    if (trips >= 2) overhead += std::max(0.0, rho - s) + (trips - 2) * std::max(0.0, 2.0 * rho - s);
    best = std::max(best, need + overhead);
  }
  return best * (1.0 - kBoundRoundingMargin);
}

namespace {

/// A target the start's scan leaves and its group's distance from the dock.
struct TripCandidate {
  double delta;
  int target;
};

/// trip_bound() over the witnesses taken, farthest first, from `candidates` (farthest first) when
/// their groups are at least `spacing` metres from those of the witnesses taken before.
double trip_bound_spaced(const CoverageInstance& in, const std::vector<TripCandidate>& candidates,
                         const std::vector<double>& start_field, double spacing) {
  const auto group_distance = [&](const std::vector<double>& field, int target) {
    double d = kInfinity;
    for (const int n : in.seen_from.row(target)) d = std::min(d, field[static_cast<std::size_t>(n)]);
    return d;
  };
  const double limit = in.range_per_charge_m * (1.0 + kBoundRoundingMargin);
  std::vector<std::uint8_t> alive(candidates.size(), 1);
  std::vector<double> deltas;
  std::vector<double> between;     // the witnesses' group distances, each pair once
  std::vector<double> from_start;  // each witness's group from the start
  std::vector<int> taken;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (alive[c] == 0) continue;
    const TripCandidate w = candidates[c];
    const std::vector<double> field = node_distances_m(in, group_cells(in, w.target));
    for (const int earlier : taken) between.push_back(group_distance(field, earlier));
    taken.push_back(w.target);
    deltas.push_back(w.delta);
    from_start.push_back(group_distance(start_field, w.target));
    for (std::size_t o = c + 1; o < candidates.size(); ++o) {
      if (alive[o] == 0) continue;
      const double d = group_distance(field, candidates[o].target);
      // Served together, a trip is at least delta_w + d + delta_o long.
      if (!(w.delta + d + candidates[o].delta > limit) || d < spacing) alive[o] = 0;
    }
  }
  if (taken.empty()) return 0.0;
  // The trips that may hold several witnesses: the last (it need not come back) and, from a start
  // away from the dock, the first. A path through k groups is at least its first group's distance
  // plus the k - 1 shortest group distances; each such trip holds at most the most k that fit.
  std::sort(between.begin(), between.end());
  const double nearest = *std::min_element(deltas.begin(), deltas.end());
  const auto most_groups = [&](double lead) {
    std::size_t k = 0;
    double length = lead;
    while (k < taken.size()) {
      if (k > 0) length += between[k - 1];  // k - 1 < n (n - 1) / 2 for k < n
      if (length > limit) break;
      ++k;
    }
    return k;
  };
  std::size_t special = most_groups(nearest);
  if (in.start_node != in.dock_node)
    special += most_groups(*std::min_element(from_start.begin(), from_start.end()) + nearest);
  // Every other witness has a trip of its own, out from the dock and back.
  double bound = 0.0;
  for (std::size_t i = special; i < deltas.size(); ++i) bound += 2.0 * deltas[i];  // deltas: descending
  return bound * (1.0 - kBoundRoundingMargin);
}

}  // namespace

double trip_bound(const CoverageInstance& in) {
  if (!in.limited_battery() || in.start_node < 0 || in.dock_node < 0) return 0.0;
  const int dock_cell = in.node_cell[static_cast<std::size_t>(in.dock_node)];
  const std::vector<double> from_dock = node_distances_m(in, std::span<const int>(&dock_cell, 1));
  const auto start_sees = in.sees.row(in.start_node);
  // Candidates: the targets the start's scan leaves, farthest group from the dock first.
  std::vector<TripCandidate> candidates;
  for (int t = 0; t < in.targets(); ++t) {
    if (!in.is_explorable(t) || std::binary_search(start_sees.begin(), start_sees.end(), t)) continue;
    double d = kInfinity;
    for (const int n : in.seen_from.row(t)) d = std::min(d, from_dock[static_cast<std::size_t>(n)]);
    if (d > 0.0 && d < kInfinity) candidates.push_back({d, t});
  }
  std::stable_sort(candidates.begin(), candidates.end(), [&](const TripCandidate& a, const TripCandidate& b) {
    if (a.delta != b.delta) return a.delta > b.delta;
    return in.seen_from.row(a.target).size() < in.seen_from.row(b.target).size();
  });
  const int start_cell = in.node_cell[static_cast<std::size_t>(in.start_node)];
  const std::vector<double> start_field =
      in.start_node == in.dock_node ? from_dock : node_distances_m(in, std::span<const int>(&start_cell, 1));
  // Witnesses close together let the last trip hold many of them; spaced farther apart, fewer
  // are taken but fewer fit in one trip. The best of a few spacings is kept.
  double best = 0.0;
  for (const double share : kTripSpacings)
    best = std::max(best, trip_bound_spaced(in, candidates, start_field, share * in.range_per_charge_m));
  return best;
}

CoverageLowerBound::CoverageLowerBound(const CoverageInstance& instance, const LowerBoundOptions& options)
    : instance_(&instance) {
  if (instance.start_node < 0) return;
  const int max_witnesses = std::max(1, options.max_witnesses);
  // Both witness sets; the one with the larger bound from the start is kept.
  std::vector<std::vector<int>> sets{farthest_first(instance, max_witnesses),
                                     fewest_viewpoints_first(instance, max_witnesses)};
  double best_bound = -1.0;
  for (std::vector<int>& set : sets) {
    CoverageLowerBound candidate(instance);
    candidate.build(std::move(set), options);
    if (candidate.at_start_ > best_bound) {
      best_bound = candidate.at_start_;
      *this = std::move(candidate);
    }
  }
  improve_witnesses(options);
  sweep_bound_ = sweep_bound(instance);
  trip_bound_ = trip_bound(instance);
  at_start_ = std::max({at_start_, sweep_bound_, trip_bound_});
}

CoverageLowerBound::CoverageLowerBound(const CoverageInstance& instance) : instance_(&instance) {}

void CoverageLowerBound::improve_witnesses(const LowerBoundOptions& options) {
  if (witnesses_.empty() || options.witness_swaps <= 0) return;
  const CoverageInstance& instance = *instance_;
  std::vector<int> pool = explorable_by_fewest_viewpoints(instance);
  if (pool.size() > kFarthestFirstCandidates) pool.resize(kFarthestFirstCandidates);
  // Trials are scored by a quicker bound: a quarter of the ascent, from the current penalties,
  // without Held-Karp; the set found is then bounded in full, and kept if that is higher.
  LowerBoundOptions quick = options;
  quick.ascent_steps = std::max(1, options.ascent_steps / 4);
  quick.held_karp_groups = 0;
  const CoverageLowerBound original = *this;
  finish(quick, pi_);
  Rng rng = make_rng(0, "optimum/witness-swaps");
  for (int trial = 0; trial < options.witness_swaps; ++trial) {
    const std::size_t k = witnesses_.size();
    const std::size_t at = uniform_below(rng, k + 1);  // k: a new witness
    const int target = pool[uniform_below(rng, pool.size())];
    if (std::find(witnesses_.begin(), witnesses_.end(), target) != witnesses_.end()) continue;
    if (at == k && static_cast<int>(k) >= options.max_witnesses) continue;
    CoverageLowerBound candidate(instance);
    candidate.witnesses_ = witnesses_;
    candidate.to_group_ = to_group_;
    std::vector<double> warm = pi_;
    std::vector<double> field = node_distances_m(instance, group_cells(instance, target));
    if (at == k) {
      candidate.witnesses_.push_back(target);
      candidate.to_group_.push_back(std::move(field));
      warm.insert(warm.begin() + static_cast<std::ptrdiff_t>(k), 0.0);  // before the robot's
    } else {
      candidate.witnesses_[at] = target;
      candidate.to_group_[at] = std::move(field);
      warm[at] = 0.0;
    }
    candidate.finish(quick, warm);
    if (candidate.at_start_ > at_start_) *this = std::move(candidate);
  }
  finish(options, {});
  if (at_start_ < original.at_start_) *this = original;
}

void CoverageLowerBound::build(std::vector<int> witnesses, const LowerBoundOptions& options) {
  const CoverageInstance& instance = *instance_;
  witnesses_ = std::move(witnesses);
  to_group_.clear();
  to_group_.reserve(witnesses_.size());
  for (const int w : witnesses_) to_group_.push_back(node_distances_m(instance, group_cells(instance, w)));
  finish(options, {});
}

void CoverageLowerBound::finish(const LowerBoundOptions& options, const std::vector<double>& warm) {
  const CoverageInstance& instance = *instance_;
  const std::size_t k = witnesses_.size();
  between_.assign(k * k, 0.0);
  for (std::size_t i = 0; i < k; ++i) {
    for (std::size_t j = 0; j < k; ++j) {
      double d = kInfinity;
      for (const int n : instance.seen_from.row(witnesses_[j]))
        d = std::min(d, to_group_[i][static_cast<std::size_t>(n)]);
      between_[i * k + j] = d;
    }
  }
  for (std::size_t i = 0; i < k; ++i) {  // symmetric: the smaller way (the grid's lengths are)
    for (std::size_t j = i + 1; j < k; ++j) {
      const double d = std::min(between_[i * k + j], between_[j * k + i]);
      between_[i * k + j] = d;
      between_[j * k + i] = d;
    }
  }
  pi_.assign(k + 1, 0.0);
  if (k == 0) return;
  // From the start: the witnesses the start's scan does not reveal.
  std::vector<int> members;
  const auto start_sees = instance.sees.row(instance.start_node);
  for (std::size_t i = 0; i < k; ++i) {
    if (!std::binary_search(start_sees.begin(), start_sees.end(), witnesses_[i]))
      members.push_back(static_cast<int>(i));
  }
  std::vector<std::uint8_t> open(k, 0);
  for (const int m : members) open[static_cast<std::size_t>(m)] = 1;
  if (options.ascent_steps > 0 && members.size() >= 2) {
    ascent_steps_ = options.ascent_steps;
    pi_ = ascend(instance.start_node, members, warm);
  }
  at_start_ = from_node(instance.start_node, open);
  // Held-Karp over the groups farthest from each other, chosen greedily from the start.
  const int want = std::clamp(options.held_karp_groups, 0, 16);
  std::vector<int> chosen;
  std::vector<double> nearest(k, kInfinity);  // to the start or a chosen group
  for (const int m : members)
    nearest[static_cast<std::size_t>(m)] =
        to_group_[static_cast<std::size_t>(m)][static_cast<std::size_t>(instance.start_node)];
  while (static_cast<int>(chosen.size()) < want) {
    int best = -1;
    for (const int m : members) {
      if (std::find(chosen.begin(), chosen.end(), m) != chosen.end()) continue;
      if (best < 0 || nearest[static_cast<std::size_t>(m)] > nearest[static_cast<std::size_t>(best)])
        best = m;
    }
    if (best < 0) break;
    chosen.push_back(best);
    for (std::size_t i = 0; i < k; ++i)
      nearest[i] = std::min(nearest[i], between_[static_cast<std::size_t>(best) * k + i]);
  }
  if (chosen.size() >= 2) at_start_ = std::max(at_start_, held_karp(instance.start_node, chosen));
}

double CoverageLowerBound::from_state(Cell at, const KnownMap& known) const {
  const int node = instance_->node_at(at);
  if (node < 0) return 0.0;
  std::vector<std::uint8_t> open(witnesses_.size(), 0);
  for (std::size_t k = 0; k < witnesses_.size(); ++k) {
    open[k] = known.is_unknown(instance_->target_cell[static_cast<std::size_t>(witnesses_[k])]) ? 1 : 0;
  }
  return from_node(node, open);
}

double CoverageLowerBound::spanning_tree(int node, const std::vector<int>& members, double* farthest) const {
  const std::size_t k = witnesses_.size();
  std::vector<double> key(members.size());
  *farthest = 0.0;
  for (std::size_t m = 0; m < members.size(); ++m) {
    key[m] = to_group_[static_cast<std::size_t>(members[m])][static_cast<std::size_t>(node)];
    *farthest = std::max(*farthest, key[m]);
  }
  if (*farthest == kInfinity) return kInfinity;
  std::vector<std::uint8_t> in_tree(members.size(), 0);
  double tree = 0.0;
  for (std::size_t step = 0; step < members.size(); ++step) {
    std::size_t best = members.size();
    for (std::size_t m = 0; m < members.size(); ++m) {
      if (in_tree[m] == 0 && (best == members.size() || key[m] < key[best])) best = m;
    }
    in_tree[best] = 1;
    tree += key[best];
    const std::size_t b = static_cast<std::size_t>(members[best]);
    for (std::size_t m = 0; m < members.size(); ++m) {
      if (in_tree[m] == 0) key[m] = std::min(key[m], between_[b * k + static_cast<std::size_t>(members[m])]);
    }
  }
  return tree;
}

double CoverageLowerBound::one_tree(int node, const std::vector<int>& members, const std::vector<double>& pi,
                                    std::vector<int>* degrees) const {
  const std::size_t k = witnesses_.size();
  const double pi_robot = pi[k];
  // Prim over the robot (position members.size()) and the groups under penalised costs.
  const std::size_t n = members.size();
  std::vector<double> key(n);
  std::vector<std::size_t> parent(n, n);  // n: the robot
  for (std::size_t m = 0; m < n; ++m) {
    const std::size_t g = static_cast<std::size_t>(members[m]);
    key[m] = to_group_[g][static_cast<std::size_t>(node)] + pi_robot + pi[g];
  }
  std::vector<std::uint8_t> in_tree(n, 0);
  double total = 0.0;
  if (degrees != nullptr) degrees->assign(k + 1, 0);
  for (std::size_t step = 0; step < n; ++step) {
    std::size_t best = n;
    for (std::size_t m = 0; m < n; ++m) {
      if (in_tree[m] == 0 && (best == n || key[m] < key[best])) best = m;
    }
    if (key[best] == kInfinity) return kInfinity;
    in_tree[best] = 1;
    total += key[best];
    const std::size_t b = static_cast<std::size_t>(members[best]);
    if (degrees != nullptr) {
      ++(*degrees)[b];
      ++(*degrees)[parent[best] == n ? k : static_cast<std::size_t>(members[parent[best]])];
    }
    for (std::size_t m = 0; m < n; ++m) {
      if (in_tree[m] != 0) continue;
      const std::size_t g = static_cast<std::size_t>(members[m]);
      const double c = between_[b * k + g] + pi[b] + pi[g];
      if (c < key[m]) {
        key[m] = c;
        parent[m] = best;
      }
    }
  }
  // The dummy end: an edge to the robot and one to the group of least penalty, both of cost 0.
  std::size_t least = static_cast<std::size_t>(members[0]);
  for (const int m : members) {
    if (pi[static_cast<std::size_t>(m)] < pi[least]) least = static_cast<std::size_t>(m);
  }
  total += pi_robot + pi[least];
  if (degrees != nullptr) {
    ++(*degrees)[k];
    ++(*degrees)[least];
  }
  double penalties = pi_robot;
  for (const int m : members) penalties += pi[static_cast<std::size_t>(m)];
  return total - 2.0 * penalties;
}

std::vector<double> CoverageLowerBound::ascend(int node, const std::vector<int>& members,
                                               const std::vector<double>& warm) const {
  const std::size_t k = witnesses_.size();
  std::vector<double> pi = warm.size() == k + 1 ? warm : std::vector<double>(k + 1, 0.0);
  std::vector<double> best_pi = pi;
  std::vector<int> degrees;
  double best = one_tree(node, members, pi, &degrees);
  if (best == kInfinity) return pi;
  // Step size: a fraction of the average edge of the tree, halved after 10 steps without gain.
  double step = best / static_cast<double>(members.size() + 1) / 2.0;
  int since_gain = 0;
  for (int it = 0; it < ascent_steps_ && step > 1e-9; ++it) {
    bool tour = true;
    for (const int m : members) tour = tour && degrees[static_cast<std::size_t>(m)] == 2;
    tour = tour && degrees[k] == 2;
    if (tour) break;  // the 1-tree is a path: the bound is that path's length, as good as it gets
    pi[k] += step * (degrees[k] - 2);
    for (const int m : members)
      pi[static_cast<std::size_t>(m)] += step * (degrees[static_cast<std::size_t>(m)] - 2);
    const double value = one_tree(node, members, pi, &degrees);
    if (value > best) {
      best = value;
      best_pi = pi;
      since_gain = 0;
    } else if (++since_gain >= 10) {
      step /= 2.0;
      since_gain = 0;
    }
  }
  return best_pi;
}

double CoverageLowerBound::from_node(int node, std::span<const std::uint8_t> open) const {
  std::vector<int> members;
  for (std::size_t i = 0; i < witnesses_.size(); ++i) {
    if (open[i] != 0) members.push_back(static_cast<int>(i));
  }
  if (members.empty()) return 0.0;
  double farthest = 0.0;
  const double tree = spanning_tree(node, members, &farthest);
  if (tree == kInfinity) return kInfinity;  // a group the robot cannot reach: no route exists
  double bound = std::max(tree, farthest);
  if (ascent_steps_ > 0) bound = std::max(bound, one_tree(node, members, pi_, nullptr));
  return bound * (1.0 - kBoundRoundingMargin);
}

double CoverageLowerBound::held_karp(int node, const std::vector<int>& groups) const {
  const std::size_t k = witnesses_.size();
  const std::size_t g = groups.size();
  const std::size_t full = (std::size_t{1} << g) - 1;
  std::vector<double> dp((full + 1) * g, kInfinity);
  for (std::size_t i = 0; i < g; ++i) {
    dp[(std::size_t{1} << i) * g + i] =
        to_group_[static_cast<std::size_t>(groups[i])][static_cast<std::size_t>(node)];
  }
  for (std::size_t mask = 1; mask <= full; ++mask) {
    for (std::size_t last = 0; last < g; ++last) {
      const double here = dp[mask * g + last];
      if ((mask & (std::size_t{1} << last)) == 0 || here == kInfinity) continue;
      const std::size_t a = static_cast<std::size_t>(groups[last]);
      for (std::size_t next = 0; next < g; ++next) {
        if ((mask & (std::size_t{1} << next)) != 0) continue;
        double& slot = dp[(mask | (std::size_t{1} << next)) * g + next];
        slot = std::min(slot, here + between_[a * k + static_cast<std::size_t>(groups[next])]);
      }
    }
  }
  double best = kInfinity;
  for (std::size_t last = 0; last < g; ++last) best = std::min(best, dp[full * g + last]);
  return best * (1.0 - kBoundRoundingMargin);
}

}  // namespace optimum
}  // namespace fsweep
