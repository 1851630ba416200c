#pragma once
/// @file lower_bound.hpp
/// A certified lower bound on the offline coverage optimum (coverage_instance.hpp), from the
/// start or from any state of a run.
///
/// Witnesses: target cells, at first chosen so that no node sees two of them (their viewpoint sets
/// seen_from are pairwise disjoint), at most LowerBoundOptions::max_witnesses: farthest first
/// (each new witness the one whose group is farthest from the start and the groups already
/// chosen, among the 4,000 targets with the fewest viewpoints), and, as a second set, hardest to see first
/// (fewest viewpoints); the set with the larger bound from the start is kept. Any route that reveals every
/// target stands, for each witness w still unrevealed, on some node of seen_from(w) (its "group"). Order the
/// groups by the route's first visit: the part of the route from the robot to the first group is at least the
/// distance to that group, and each part between two consecutive first visits at least the distance between
/// the two groups (the shortest path between any node of one and any node of the other). So the route is at
/// least the length of a path that starts at the robot and visits every group, in the graph whose edges are
/// those group distances, and so at least:
/// - the minimum spanning tree over the robot and the groups (a path is a spanning tree), and
///   its Lagrangian strengthening, Held and Karp's 1-tree bound with penalties found by
///   subgradient ascent from the start (valid for any penalties, so also from later states),
/// - the shortest such path over any subset of the groups (Held-Karp's dynamic programme, exact
///   over at most 12 groups, used from the start where it is affordable),
/// - and the distance to the farthest group.
/// The witness set then goes through a seeded local search (LowerBoundOptions::witness_swaps):
/// swapping one witness for another target, or adding one, is kept when the bound from the start
/// rises. Witnesses need not have disjoint groups for the bound to hold (groups that share a node
/// are 0 apart); disjoint groups are only what makes them useful.
/// The bound from a state ignores the battery (a relaxation: trips back to the dock only add
/// length), so it is valid with any battery. From the start it is also at least sweep_bound()
/// and trip_bound(), which count the battery. Lengths are exact octile sums (search/grid_search.hpp); the
/// bound is lowered by a relative 1e-9 against the rounding of the sums.
///
/// Cost per call (from_state): O(k^2) for k unrevealed witnesses, no search. Set-up: one
/// multi-source Dijkstra per witness over the map, k^2 group distances.

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "optimum/coverage_instance.hpp"
#include "world/known_map.hpp"

namespace fsweep {
inline namespace optimum {

struct LowerBoundOptions {
  /// Most witnesses (>= 1). More make the bound stronger and each call slower (k^2).
  int max_witnesses = 96;
  /// Subgradient steps of the 1-tree bound at the start (0: spanning tree only).
  int ascent_steps = 200;
  /// Groups of Held-Karp's exact path bound at the start (0: off; at most 16).
  int held_karp_groups = 12;
  /// Trials of the witness search at the start: each replaces one witness by a random target
  /// among the hardest to see (or adds it) and keeps the change when the bound from the start
  /// rises (a seeded, deterministic search; 0: off). One distance field per trial.
  int witness_swaps = 1000;
};

/// The sweep bound from the start: a step from node a to node b reveals at most the targets b's
/// scan sees and a's does not; `rate` is the most of those per metre over every allowed step of
/// the map. Let d(t) be the distance from the dock to the nearest node that sees target t, and
/// N(rho) the targets the start's scan leaves with d(t) >= rho. Each is revealed by a step that
/// ends at least rho from the dock, so such steps add up to at least N(rho) / rate metres. A
/// stretch between two charges (range R per charge) spends at least rho - s getting there (s the
/// longest step; from the start, delta nearer the dock) and rho coming back (not on the last
/// stretch), so it holds at most R - 2 rho + s metres of such steps (R - rho + s on the last,
/// R - 2 rho + s + delta on the first, R - rho + s + delta when it is the only one); the fewest stretches
/// that hold N(rho) / rate, with their ways there and back, give the bound at rho; the largest over all rho
/// is kept. Without a battery it is N(rho) / rate plus the way there. Cost: one set difference per step of
/// the map.
[[nodiscard]] double sweep_bound(const CoverageInstance& instance);

/// The trip bound from the start, with a battery (0 without): every target must be seen from a
/// node of its group, and a trip from the dock that reaches the group of target t is at least
/// 2 delta(t) long (delta(t): the group's distance from the dock). Witnesses are taken farthest
/// group first, each only when no trip within one charge (range R) can reach its group and the
/// group of any witness taken before (delta_a + d(a, b) + delta_b > R, d the group distance), so
/// every trip out from the dock and back holds at most one of them. Only the last trip (it need
/// not come back) and, from a start away from the dock, the first can hold several: at most the
/// most k whose shortest path through k groups (the nearest group's distance plus the k - 1
/// shortest group distances) fits in one charge. The bound is 2 delta summed over the witnesses
/// but those (the farthest) the two trips may hold. Witnesses close together let the last trip
/// hold many, so the witnesses are taken again with their groups at least a spacing apart (0,
/// 1/64, ..., 1/4 of the range per charge) and the largest bound kept. Cost per spacing: one
/// distance field per witness and a pass over the candidates' viewpoints for each.
[[nodiscard]] double trip_bound(const CoverageInstance& instance);

class CoverageLowerBound {
 public:
  CoverageLowerBound(const CoverageInstance& instance, const LowerBoundOptions& options);

  /// The bound from the start of a run: the robot on the start node, having revealed what the
  /// start's scan reveals. Held-Karp included.
  [[nodiscard]] double at_start() const { return at_start_; }
  /// sweep_bound() from the start; at_start() is at least this.
  [[nodiscard]] double start_sweep_bound() const { return sweep_bound_; }
  /// trip_bound() from the start; at_start() is at least this.
  [[nodiscard]] double start_trip_bound() const { return trip_bound_; }

  /// The bound from a run's state: the robot at `at` (a node), `known` the cells revealed so far
  /// (a witness counts as revealed when its cell is known). The battery is not used (see above).
  /// 0 when `at` is not a node or no witness is unrevealed.
  [[nodiscard]] double from_state(Cell at, const KnownMap& known) const;

  /// The bound from node `node` with open[k] != 0 for the witnesses k still unrevealed
  /// (open.size() == witnesses().size()): the larger of the spanning-tree and farthest-group
  /// bounds.
  [[nodiscard]] double from_node(int node, std::span<const std::uint8_t> open) const;

  /// The witnesses (target ids), in the order chosen.
  [[nodiscard]] const std::vector<int>& witnesses() const { return witnesses_; }
  /// Distance (metres) from node `node` to the group of witness k.
  [[nodiscard]] double to_group_m(int k, int node) const {
    return to_group_[static_cast<std::size_t>(k)][static_cast<std::size_t>(node)];
  }

 private:
  /// Held-Karp over the `groups` (indices of witnesses) from node `node`.
  [[nodiscard]] double held_karp(int node, const std::vector<int>& groups) const;
  /// The Lagrangian 1-tree bound (Held and Karp 1970) on a path from `node` through the groups
  /// `members` with penalties `pi` (one per witness, plus the robot's last): a spanning tree
  /// over the robot and the groups under costs c(i, j) + pi_i + pi_j, plus the two edges of a
  /// dummy end node (to the robot and to the group of least penalty, both of cost 0), minus
  /// 2 x the penalties. A lower bound for any penalties. `degrees` (optional, same indexing as
  /// pi) receives each node's degree in that tree.
  [[nodiscard]] double one_tree(int node, const std::vector<int>& members, const std::vector<double>& pi,
                                std::vector<int>* degrees) const;
  /// Penalties that raise one_tree() from `node` (subgradient ascent, a fixed number of steps),
  /// from `warm` when it holds one penalty per witness and the robot's, else from 0.
  [[nodiscard]] std::vector<double> ascend(int node, const std::vector<int>& members,
                                           const std::vector<double>& warm) const;
  /// from_node() without the 1-tree.
  [[nodiscard]] double spanning_tree(int node, const std::vector<int>& members, double* farthest) const;

  /// An empty bound over `instance`, filled by build().
  explicit CoverageLowerBound(const CoverageInstance& instance);
  /// The group distances, penalties and start bound of one witness set.
  void build(std::vector<int> witnesses, const LowerBoundOptions& options);
  /// build() once to_group_ holds the witnesses' distance fields; the ascent starts from `warm`.
  void finish(const LowerBoundOptions& options, const std::vector<double>& warm);
  /// The witness search (LowerBoundOptions::witness_swaps).
  void improve_witnesses(const LowerBoundOptions& options);

  const CoverageInstance* instance_;
  int ascent_steps_ = 0;
  std::vector<int> witnesses_;
  std::vector<std::vector<double>> to_group_;  // [k][node]
  std::vector<double> between_;                // k x k, group to group (symmetric: the smaller way)
  std::vector<double> pi_;                     // penalties found from the start (k + 1)
  double at_start_ = 0.0;
  double sweep_bound_ = 0.0;
  double trip_bound_ = 0.0;
};

/// The relative margin the bounds are lowered by against rounding.
inline constexpr double kBoundRoundingMargin = 1e-9;

}  // namespace optimum
}  // namespace fsweep
