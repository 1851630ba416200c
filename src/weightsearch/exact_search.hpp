#pragma once
/// @file exact_search.hpp
/// The exact weight search (docs/dev/architecture.md, "The exact weight search"): every distinct
/// behaviour of a linear-scored strategy over a whole grid of weight vectors, by decision
/// sharing. One simulation starts with the region of every weight vector; at each decision
/// whose choice depends on the weights (Simulation::choice()), the region is split by which
/// candidate argmin_linear() chooses at each of its points (WeightGrid::split()), the
/// simulation is forked once per non-empty share, and each fork goes on with its share. Each
/// finished simulation is one behaviour, produced by exactly the weight vectors of its region:
/// for each of them, a run with those weights alone makes the same choices, so it ends the same
/// way with the same quality metrics (effort metrics, the `*_time_s` and `*_expansions`
/// columns, measure the shared search instead).
///
/// A class of instances (several maps, seeds or repetitions) is searched jointly: a region
/// carries one simulation per instance and splits wherever any of them splits, so a behaviour
/// is one run per instance, all produced by the same weight vectors.

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "sim/run_result.hpp"
#include "sim/run_spec.hpp"
#include "sim/simulation.hpp"
#include "weightsearch/search_order.hpp"
#include "weightsearch/weight_grid.hpp"

namespace fsweep {
inline namespace weightsearch {

/// One behaviour: the weight vectors that produce it and its run.
struct Behaviour {
  /// The candidate chosen at each decision that split its region (the path in the region tree).
  std::vector<int> choices;
  /// A hash of every decision of its runs (Simulation::decision_trace(), instance by instance):
  /// the behaviour's identity. Two searches of parts of one grid (shards) find one behaviour
  /// of the whole grid's search as behaviours with the same trace, since the whole search
  /// separates two vectors exactly when some decision differs.
  std::uint64_t trace = 0;
  /// Its weight vectors.
  WeightRegion region;
  /// How many.
  std::uint64_t vectors = 0;
  /// The lexicographically smallest of them and, per weight, the smallest and largest index
  /// among them (indices into the grid's value lists).
  std::array<int, WeightGrid::kMaxWeights> representative{};
  std::array<std::array<int, 2>, WeightGrid::kMaxWeights> bounds{};
  /// The run of each instance, in the order of exact_search()'s `instances`.
  std::vector<RunResult> results;
};

/// A leaf of the region tree that branch and bound does not report as a behaviour: a region it
/// pruned, or a finished behaviour that a better one beat. With the behaviours it reports they
/// partition the searched region, which is what its certificate lists
/// (docs/dev/weight-search-design.md, "The certificate").
struct CertifiedLeaf {
  enum class Kind { Pruned, Beaten };
  Kind kind = Kind::Pruned;
  /// Its weight vectors and its path in the region tree (as Behaviour::choices).
  const WeightRegion* region = nullptr;
  std::span<const int> choices;
  /// The vectors in it.
  std::uint64_t vectors = 0;
  /// Pruned: the lower bound that exceeded the best objective then known. Beaten: its objective
  /// (NaN: none). Both as BranchAndBound minimises them.
  double value = 0.0;
  /// Pruned: per instance, Simulation::steps_taken() of its runs when the bound was taken (the
  /// runs of any vector of the region are in that state then). Beaten: empty.
  std::vector<std::uint64_t> steps;
  /// Beaten: its decisions' hash (as Behaviour::trace). Pruned: 0.
  std::uint64_t trace = 0;
};

/// Where branch and bound stands while it runs (docs/weight-search.md, "Boxes out of reach"):
/// the optimum of the searched region lies in [lower, best].
struct AnytimeState {
  /// The smallest objective finished so far (+infinity: none yet).
  double best = std::numeric_limits<double>::infinity();
  /// A certified lower bound of every objective in the region: the smaller of `best` and the
  /// bounds of the branches not yet resolved (each admissible; a branch's bound is the one
  /// taken at its last decision, or at the split that created it, so it may lag behind).
  double lower = -std::numeric_limits<double>::infinity();
  /// Branches not yet resolved.
  std::size_t open_branches = 0;
};

/// Branch and bound: the search for the behaviours that minimise an objective, leaving out
/// regions that provably cannot hold one.
struct BranchAndBound {
  /// The objective of a finished behaviour (its runs, one per instance); NaN: no value (such a
  /// behaviour is never optimal).
  std::function<double(const std::vector<RunResult>&)> objective;
  /// A lower bound of the objective of every behaviour whose runs go on from `sims` (one per
  /// instance, some possibly ended): admissible, i.e. never above such a behaviour's
  /// objective, so that pruning a region whose bound exceeds a finished behaviour's objective
  /// never loses an optimal behaviour. -infinity when nothing is known.
  std::function<double(std::span<const Simulation>)> lower_bound;
  /// Called with the vector count of each pruned region (progress), from any thread, possibly
  /// at once; may be empty.
  std::function<void(std::uint64_t)> on_pruned;
  /// Called for every leaf not reported as a behaviour (as on_behaviour: from any thread, never
  /// at once with it or another call); may be empty.
  std::function<void(const CertifiedLeaf&)> on_leaf;
  /// The objective of a behaviour known before the search (e.g. found by a killed search that
  /// is resumed): regions whose bound exceeds it are pruned from the start. +infinity: none.
  double incumbent = std::numeric_limits<double>::infinity();
  /// Called with the search's AnytimeState once its root's branch is open (after the probes), then
  /// at most once every `anytime_interval_s` seconds while it runs (as on_behaviour: from any
  /// thread, never at once with another call); may be empty.
  /// ExactSearchStats holds the state at the end.
  std::function<void(const AnytimeState&)> on_anytime;
  double anytime_interval_s = 5.0;
  /// Grid points (indices, as Behaviour::representative) run alone before the search, each
  /// on every instance, the best of their objectives the first incumbent (below `incumbent`,
  /// else ignored): branch and bound prunes from the start with a good one instead of the first
  /// dive's. Points outside the searched region are left out. Each is some vector's objective,
  /// so no optimal behaviour is pruned; only the time and the certificate's partition change.
  std::vector<std::array<int, WeightGrid::kMaxWeights>> probes;
  /// Called with each finished probe's point and objective (NaN: none), as on_behaviour; may be
  /// empty. A probe cut short by a stop is not reported.
  std::function<void(const std::array<int, WeightGrid::kMaxWeights>&, double)> on_probe;
  /// The order of exploration, and SearchOrder::Bound's most waiting branches (>= 1).
  SearchOrder order = SearchOrder::Depth;
  std::size_t max_open = kDefaultMaxOpenBranches;
};

/// What an exact search did.
struct ExactSearchStats {
  /// Behaviours found, decisions that split a region, simulations forked.
  std::uint64_t behaviours = 0;
  std::uint64_t splits = 0;
  std::uint64_t forks = 0;
  /// The steps its branches' runs took (Simulation::step() and step_choosing() calls; the probes'
  /// not counted): its simulation work, which the sharing of decisions keeps down.
  std::uint64_t steps = 0;
  /// Branch and bound only: the certificate. Regions pruned, the vectors in them, and the
  /// smallest lower bound among them (infinity when none was pruned): every pruned vector's
  /// objective is at least that, above `best`, the optimum. These counts depend on the order
  /// in which threads finish behaviours; the optimal behaviours do not.
  std::uint64_t pruned_regions = 0;
  std::uint64_t pruned_vectors = 0;
  double smallest_pruned_bound = std::numeric_limits<double>::infinity();
  double best = std::numeric_limits<double>::infinity();
  /// Branch and bound only: the smallest bound of the branches a stop left unresolved (each a
  /// lower bound of every objective in its region), +infinity when none was left.
  double unresolved_bound = std::numeric_limits<double>::infinity();
  std::size_t unresolved_branches = 0;
  /// Branch and bound only: the probes run (BranchAndBound::probes inside the region) and the
  /// best of their objectives (+infinity: none had one).
  std::size_t probes = 0;
  double best_probe = std::numeric_limits<double>::infinity();
  /// True when `stop` ended the search early: the behaviours it reported and the subtrees it
  /// journaled are finished, the rest of the grid is not resolved (a rerun with the journal
  /// searches it).
  bool stopped = false;
};

/// What a finished subtree of the region tree resolved: the counts of its leaves.
struct SubtreeTally {
  /// Weight vectors in it.
  std::uint64_t vectors = 0;
  /// Finished behaviours (every one; in mode best also those a better one beat).
  std::uint64_t behaviours = 0;
  /// Branch and bound: pruned regions, their vectors and their smallest lower bound.
  std::uint64_t pruned_regions = 0;
  std::uint64_t pruned_vectors = 0;
  double smallest_pruned_bound = std::numeric_limits<double>::infinity();
  void add(const SubtreeTally& other);
};

/// The id of the region tree's root for a search of `root` (a hash of its boxes and parts), and
/// of the node reached from node `parent` by choosing `choice` at a decision that split it (a
/// 64-bit hash of the path from the root, so a node has the same id in every search of the same
/// root: the tree is a function of the root and the instances).
[[nodiscard]] std::uint64_t subtree_root(const WeightRegion& root);
[[nodiscard]] std::uint64_t subtree_child(std::uint64_t parent, int choice);
/// The id of the node reached from the root `root` by the choices `choices` (Behaviour::choices).
[[nodiscard]] std::uint64_t subtree_of(std::uint64_t root, std::span<const int> choices);

/// Resuming a killed search without visiting what it finished: the subtrees it finished are
/// skipped, whole, the moment a split creates them.
struct SubtreeJournal {
  /// The finished subtrees of a killed search of the same root, by id: leaves (its behaviours)
  /// and nodes whose every leaf had finished or been pruned.
  const std::unordered_map<std::uint64_t, SubtreeTally>* done = nullptr;
  /// The ancestors of those finished subtrees, by id (journal_ancestors()): branch and bound
  /// never prunes one whole, which would resolve its finished parts twice; it goes on to its
  /// splits, where they are skipped. May be null.
  const std::unordered_set<std::uint64_t>* ancestors = nullptr;
  /// Called when a node that split has finished, with its id and what its leaves resolved (as
  /// on_behaviour, from any thread but never at once with another call of either); may be empty.
  std::function<void(std::uint64_t, const SubtreeTally&)> on_done;
  /// Called with the id and vector count of each skipped subtree (progress), from any thread,
  /// possibly at once; may be empty.
  std::function<void(std::uint64_t, std::uint64_t)> on_skipped;
};

/// The ids of the nodes above journaled finished leaves reached by `choices` from `root`
/// (subtree_root()): every proper prefix of each, the root included, for SubtreeJournal::ancestors.
[[nodiscard]] std::unordered_set<std::uint64_t> journal_ancestors(std::uint64_t root,
                                                                  std::span<const std::vector<int>> choices);

/// The topmost of a journal's finished subtrees `done` (leaves included) down the paths
/// `choices` of its leaves from `root`: on each path the first node `done` holds. A search
/// resumed with SubtreeJournal::ancestors = journal_ancestors(root, choices) skips each once
/// when it comes to it and goes below none (it never prunes above one), so `vectors`, theirs
/// summed, is what the journal resolved. Without those ancestors, branch and bound may prune a
/// region that holds some of them, and their vectors would count twice.
struct JournalTop {
  std::unordered_set<std::uint64_t> ids;
  std::uint64_t vectors = 0;
};
[[nodiscard]] JournalTop journal_topmost(std::uint64_t root, std::span<const std::vector<int>> choices,
                                         const std::unordered_map<std::uint64_t, SubtreeTally>& done);

/// `count` grid points spread over `region` for BranchAndBound::probes: the grid's middle point
/// if the region holds it, then seeded uniform points of the grid that lie in it (at most 64 x
/// `count` tries), no point twice. A pure function of its arguments.
[[nodiscard]] std::vector<std::array<int, WeightGrid::kMaxWeights>> spread_probes(const WeightGrid& grid,
                                                                                  const WeightRegion& region,
                                                                                  std::size_t count,
                                                                                  std::uint64_t seed);

/// Searches `grid` for the class `instances` (at least one), whose strategies must be
/// linear-scored with grid.weights() features (their own weights do not matter). Calls `on_behaviour` once
/// per behaviour, from any thread but never two at once, in an order that depends on the threads (sort by
/// `choices` or `representative` for a fixed order). `threads` >= 1 (oneTBB tasks over the
/// region tree). Throws ConfigError for a bad spec, std::invalid_argument for a strategy that is
/// not linear-scored, has another number of weights than the grid, or does not allow one of the
/// grid's values (LinearScoredStrategy::set_weights).
///
/// With `bnb`, only the behaviours that minimise bnb->objective are sure to be reported:
/// on_behaviour gets every finished behaviour whose objective is at most the best one found so
/// far (the caller keeps those equal to the final ExactSearchStats::best; ties are all kept),
/// and a region is pruned, without finishing its runs, when bnb->lower_bound exceeds that best.
///
/// With `within`, only its vectors are searched (a shard, WeightGrid::shard()): a behaviour
/// found then has the part of the whole search's behaviour that lies in `within` (the same
/// runs and trace).
///
/// With `journal`, the subtrees in journal->done are skipped: their behaviours are not
/// reported again, and their tallies count in the returned stats (behaviours, pruned regions
/// and vectors, smallest pruned bound; not splits and forks, which count this search's work).
///
/// With `stop`, the search ends soon after *stop becomes true (e.g. set by a signal handler):
/// every branch returns at its next decision or step without finishing, so its node and their
/// ancestors are neither finished nor journaled, and ExactSearchStats::stopped says so.
ExactSearchStats exact_search(std::span<const RunSpec> instances, const WeightGrid& grid, int threads,
                              const std::function<void(Behaviour&&)>& on_behaviour,
                              const BranchAndBound* bnb = nullptr, const WeightRegion* within = nullptr,
                              const SubtreeJournal* journal = nullptr,
                              const std::atomic<bool>* stop = nullptr);

}  // namespace weightsearch
}  // namespace fsweep
