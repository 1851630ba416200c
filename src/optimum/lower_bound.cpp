#include "optimum/lower_bound.hpp"

#include <algorithm>
#include <numeric>

namespace fsweep {
inline namespace optimum {
namespace {

/// Witnesses: explorable targets by fewest viewpoints (then by id), each taken when none of its
/// viewpoints is a viewpoint of a witness taken before.
std::vector<int> choose_witnesses(const CoverageInstance& in, int max_witnesses) {
  std::vector<int> order;
  for (int t = 0; t < in.targets(); ++t) {
    const auto from = in.seen_from.row(t);
    const bool usable = std::any_of(from.begin(), from.end(),
                                    [&](int n) { return in.node_usable[static_cast<std::size_t>(n)] != 0; });
    if (usable) order.push_back(t);
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return in.seen_from.row(a).size() < in.seen_from.row(b).size(); });
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

}  // namespace

CoverageLowerBound::CoverageLowerBound(const CoverageInstance& instance, const LowerBoundOptions& options)
    : instance_(&instance), witnesses_(choose_witnesses(instance, std::max(1, options.max_witnesses))) {
  const std::size_t k = witnesses_.size();
  to_group_.reserve(k);
  std::vector<int> cells;
  for (const int w : witnesses_) {
    cells.clear();
    for (const int n : instance.seen_from.row(w))
      cells.push_back(instance.node_cell[static_cast<std::size_t>(n)]);
    to_group_.push_back(node_distances_m(instance, cells));
  }
  between_.assign(k * k, 0.0);
  for (std::size_t i = 0; i < k; ++i) {
    for (std::size_t j = 0; j < k; ++j) {
      double d = kInfinity;
      for (const int n : instance.seen_from.row(witnesses_[j]))
        d = std::min(d, to_group_[i][static_cast<std::size_t>(n)]);
      between_[i * k + j] = d;
    }
  }
  if (instance.start_node < 0 || k == 0) return;
  // From the start: the witnesses the start's scan does not reveal.
  std::vector<std::uint8_t> open(k, 1);
  for (const int t : instance.sees.row(instance.start_node)) {
    const auto it = std::find(witnesses_.begin(), witnesses_.end(), t);
    if (it != witnesses_.end()) open[static_cast<std::size_t>(it - witnesses_.begin())] = 0;
  }
  at_start_ = from_node(instance.start_node, open);
  // Held-Karp over the groups farthest from each other, chosen greedily from the start.
  const int want = std::clamp(options.held_karp_groups, 0, 16);
  std::vector<int> chosen;
  std::vector<double> nearest(k, kInfinity);  // to the start or a chosen group
  for (std::size_t i = 0; i < k; ++i) {
    if (open[i] != 0) nearest[i] = to_group_[i][static_cast<std::size_t>(instance.start_node)];
  }
  while (static_cast<int>(chosen.size()) < want) {
    int best = -1;
    for (std::size_t i = 0; i < k; ++i) {
      if (open[i] == 0 || std::find(chosen.begin(), chosen.end(), static_cast<int>(i)) != chosen.end())
        continue;
      if (best < 0 || nearest[i] > nearest[static_cast<std::size_t>(best)]) best = static_cast<int>(i);
    }
    if (best < 0) break;
    chosen.push_back(best);
    for (std::size_t i = 0; i < k; ++i) {
      nearest[i] = std::min(nearest[i], std::min(between_[static_cast<std::size_t>(best) * k + i],
                                                 between_[i * k + static_cast<std::size_t>(best)]));
    }
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

double CoverageLowerBound::from_node(int node, std::span<const std::uint8_t> open) const {
  const std::size_t k = witnesses_.size();
  // Prim over the robot (index k) and the open groups; distances between groups are taken as
  // the smaller of the two directions (the grid's lengths are symmetric; the min keeps the bound
  // valid whatever rounding does).
  std::vector<int> members;
  for (std::size_t i = 0; i < k; ++i) {
    if (open[i] != 0) members.push_back(static_cast<int>(i));
  }
  if (members.empty()) return 0.0;
  double farthest = 0.0;
  std::vector<double> key(members.size());
  for (std::size_t m = 0; m < members.size(); ++m) {
    key[m] = to_group_[static_cast<std::size_t>(members[m])][static_cast<std::size_t>(node)];
    farthest = std::max(farthest, key[m]);
  }
  if (farthest == kInfinity) return kInfinity;  // a group the robot cannot reach: no route exists
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
      if (in_tree[m] != 0) continue;
      const std::size_t j = static_cast<std::size_t>(members[m]);
      key[m] = std::min(key[m], std::min(between_[b * k + j], between_[j * k + b]));
    }
  }
  return std::max(tree, farthest) * (1.0 - kBoundRoundingMargin);
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
        const std::size_t b = static_cast<std::size_t>(groups[next]);
        const double step = std::min(between_[a * k + b], between_[b * k + a]);
        double& slot = dp[(mask | (std::size_t{1} << next)) * g + next];
        slot = std::min(slot, here + step);
      }
    }
  }
  double best = kInfinity;
  for (std::size_t last = 0; last < g; ++last) best = std::min(best, dp[full * g + last]);
  return best * (1.0 - kBoundRoundingMargin);
}

}  // namespace optimum
}  // namespace fsweep
