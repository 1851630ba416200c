#include "weightsearch/exact_search.hpp"

#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/task_arena.h>
#include <oneapi/tbb/task_group.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/random.hpp"
#include "sim/simulation.hpp"

namespace fsweep {
inline namespace weightsearch {
namespace {

/// A node of the region tree (the stretch of a branch between two splits), kept while some of
/// its subtree is unfinished: what its finished leaves resolved, and how many parts of it are
/// still going (its own stretch until it splits, then its unfinished children).
struct Node {
  std::uint64_t id = 0;
  std::shared_ptr<Node> parent;
  int pending = 1;
  bool split = false;
  SubtreeTally tally;
};

/// Branch and bound's bounds of the branches not yet resolved (AnytimeState::lower), one slot per
/// branch. Used under the Explorer's mutex.
class OpenBounds {
 public:
  using Slot = std::multiset<double>::iterator;
  Slot open(double bound) { return bounds_.insert(bound); }
  Slot raise(Slot slot, double bound) {
    auto node = bounds_.extract(slot);
    node.value() = bound;
    return bounds_.insert(std::move(node));
  }
  void close(Slot slot) { bounds_.erase(slot); }
  /// The smallest bound (+infinity: none open).
  [[nodiscard]] double lowest() const {
    return bounds_.empty() ? std::numeric_limits<double>::infinity() : *bounds_.begin();
  }
  [[nodiscard]] std::size_t size() const { return bounds_.size(); }

 private:
  std::multiset<double> bounds_;
};

/// A branch's slot in OpenBounds and the bound it holds (branch and bound only).
struct OpenSlot {
  OpenBounds::Slot slot;
  double bound = 0.0;
};

/// One branch of the region tree being explored: one simulation per instance and the weight
/// vectors they stand for.
struct Branch {
  std::vector<Simulation> sims;
  WeightRegion region;
  std::vector<int> choices;
  std::shared_ptr<Node> node;
  /// The region's bounds (WeightGrid::bounds) and size, once computed: they change only at a
  /// split.
  std::optional<std::array<std::array<int, 2>, WeightGrid::kMaxWeights>> box;
  std::optional<std::uint64_t> vectors;
  std::optional<WeightDirections> directions;
  /// Its directions in the coordinates of tied features (WeightGrid::tied_directions), for
  /// signs -1 and +1, built the first time the plain directions do not settle a decision.
  std::array<std::optional<WeightDirections>, 2> tied;
  /// Branch and bound: its slot among the open bounds, until it is resolved.
  std::optional<OpenSlot> open;
};

class Explorer {
 public:
  Explorer(const WeightGrid& grid, tbb::task_group& tasks,
           const std::function<void(Behaviour&&)>& on_behaviour, const BranchAndBound* bnb,
           const SubtreeJournal* journal, const std::atomic<bool>* stop)
      : grid_(grid), tasks_(tasks), on_behaviour_(on_behaviour), bnb_(bnb), journal_(journal), stop_(stop) {
    if (bnb_ != nullptr) best_.store(bnb_->incumbent);
  }

  /// True (and counted) when the journal holds node `id` finished: its subtree is not searched.
  bool skipped(std::uint64_t id, const std::shared_ptr<Node>& parent) {
    if (journal_ == nullptr || journal_->done == nullptr) return false;
    const auto it = journal_->done->find(id);
    if (it == journal_->done->end()) return false;
    const SubtreeTally& t = it->second;
    behaviours_.fetch_add(t.behaviours, std::memory_order_relaxed);
    pruned_regions_.fetch_add(t.pruned_regions, std::memory_order_relaxed);
    pruned_vectors_.fetch_add(t.pruned_vectors, std::memory_order_relaxed);
    lower_to(smallest_pruned_bound_, t.smallest_pruned_bound);
    if (parent != nullptr) {
      const std::lock_guard<std::mutex> lock(mutex_);
      parent->tally.add(t);
    }
    if (journal_->on_skipped) journal_->on_skipped(id, t.vectors);
    return true;
  }

  /// Follows `b` to the end of its runs, forking a task for every share but the last at each
  /// split (the last goes on in this one). Each instance in turn advances until it ends or comes
  /// to a decision that splits the region (advance()); then the region splits at the first
  /// instance's such decision, and every share goes on from there, the other instances held at
  /// theirs. So what the region's vectors do alike on every instance is simulated once for the
  /// region, not again for each share of a split on an earlier instance. A stopped search leaves
  /// `b` at its next decision or step, unfinished (its node is never released).
  void explore(Branch b) {
    for (;;) {
      if (stopping()) return;
      if (!b.vectors) b.vectors = grid_.count(b.region);
      if (pruned(b)) return;
      if (*b.vectors == 1) return run_alone(std::move(b));
      std::optional<std::size_t> split_at;
      std::vector<WeightGrid::Share> shares;
      for (std::size_t instance = 0; instance < b.sims.size(); ++instance) {
        std::vector<WeightGrid::Share> held;
        if (!advance(b, instance, held)) return;
        if (!held.empty() && !split_at) {
          split_at = instance;
          shares = std::move(held);
        }
      }
      if (!split_at) return finish(std::move(b));
      if (!fork(b, shares, *split_at)) return;
      step(b.sims[*split_at], b.choices.back());
    }
  }

  /// Steps instance `instance` of `b` while every vector of the region makes the same choice:
  /// until its run ends, or until a decision splits the region into `shares` (returned there; the
  /// run keeps the decision's candidates, Simulation::pending_choice(), so a share of a split
  /// elsewhere takes them up without asking again: they hold every candidate a vector of this
  /// region, and so of any part of it, may choose). False when `b` was pruned or the search
  /// stopped (`b` is then gone).
  bool advance(Branch& b, std::size_t instance, std::vector<WeightGrid::Share>& shares) {
    Simulation& sim = b.sims[instance];
    while (!sim.ended()) {
      if (stopping() || pruned(b)) return false;
      const Candidates* candidates = sim.pending_choice();
      if (candidates == nullptr) candidates = choice(b, sim);
      if (candidates == nullptr) {  // a decision no weight changes
        step(sim);
        continue;
      }
      if (candidates->cells.size() == 1) {  // the only candidate any weight vector here may choose
        step(sim, 0);
        continue;
      }
      const WeightDirections* tied_directions = nullptr;
      if (const int sole = sole_choice(b, *candidates, tied_directions); sole >= 0) {
        step(sim, sole);
        continue;
      }
      std::vector<WeightGrid::Share> split = grid_.split(b.region, *candidates, tied_directions);
      if (split.size() == 1) {
        step(sim, split.front().candidate);
        continue;
      }
      shares = std::move(split);
      return true;
    }
    return true;
  }

  /// sim.step() (candidate < 0) or sim.step_choosing(candidate), counted unless the run had
  /// ended; its result.
  bool step(Simulation& sim, int candidate = -1) {
    if (!sim.ended()) steps_.fetch_add(1, std::memory_order_relaxed);
    return candidate < 0 ? sim.step() : sim.step_choosing(candidate);
  }

  /// The rest of a branch down to one vector: its runs alone, by the strategy's own (cheaper)
  /// decisions.
  void run_alone(Branch b) {
    const std::vector<double> weights = grid_.weights_at(grid_.lexmin(b.region));
    for (Simulation& s : b.sims) {
      s.set_weights(weights);
      while (step(s)) {
        if (stopping() || pruned(b)) return;
      }
    }
    finish(std::move(b));
  }

  /// The candidates of `sim`'s next decision for the vectors of `b`'s region (Simulation::choice,
  /// given the region's bounding box and its directions), or null for a decision no weight
  /// changes.
  const Candidates* choice(Branch& b, Simulation& sim) {
    if (!b.box) b.box = grid_.bounds(b.region);
    const auto& box = *b.box;
    std::array<double, WeightGrid::kMaxWeights> lo{};
    std::array<double, WeightGrid::kMaxWeights> hi{};
    const auto n = static_cast<std::size_t>(grid_.weights());
    for (std::size_t k = 0; k < n; ++k) {
      lo[k] = grid_.values(static_cast<int>(k))[static_cast<std::size_t>(box[k][0])];
      hi[k] = grid_.values(static_cast<int>(k))[static_cast<std::size_t>(box[k][1])];
    }
    return sim.choice(WeightBounds{std::span(lo).first(n), std::span(hi).first(n), directions(b)});
  }

  /// `b`'s region's directions (WeightGrid::directions), computed once per region.
  const WeightDirections& directions(Branch& b) {
    if (!b.directions) b.directions = grid_.directions(b.region);
    return *b.directions;
  }

  /// The candidate every vector of `b`'s region chooses, when its directions prove it without
  /// visiting its points (most decisions of a narrow region do not split it, though several
  /// candidates can win in its bounding box), else -1. For tied candidates `tied_directions` is
  /// set to the region's directions in their coordinates, for split().
  int sole_choice(Branch& b, const Candidates& candidates, const WeightDirections*& tied_directions) {
    const int sole = grid_.sole_choice(directions(b), candidates);
    const int sign = sole < 0 ? WeightGrid::tied_sign(candidates) : 0;
    if (sign == 0) return sole;
    // The energy-aware costs depend on w2 - w3 (or w2 + w3): in those coordinates a region's
    // directions are narrow where w / sum(w) is not (WeightGrid::tied_sign()).
    std::optional<WeightDirections>& tied = b.tied[sign < 0 ? 0 : 1];
    if (!tied) tied = grid_.tied_directions(b.region, sign);
    tied_directions = &*tied;
    return grid_.sole_choice_tied(*tied, sign, candidates);
  }

  /// A split of `b` (at instance `instance`'s decision) into `shares`: a child node per share,
  /// but for those the journal holds finished; a task for each share's branch but the last, which
  /// `b` becomes (its choice appended, not yet stepped). False when the last is finished too.
  bool fork(Branch& b, std::vector<WeightGrid::Share>& shares, std::size_t instance) {
    splits_.fetch_add(1, std::memory_order_relaxed);
    forks_.fetch_add(shares.size() - 1, std::memory_order_relaxed);
    // The parent's count of unfinished parts grows by the children before its own stretch ends.
    std::vector<std::shared_ptr<Node>> children(shares.size());
    int created = 0;
    for (std::size_t s = 0; s < shares.size(); ++s) {
      const std::uint64_t id = subtree_child(b.node->id, shares[s].candidate);
      if (skipped(id, b.node)) continue;
      children[s] = std::make_shared<Node>(Node{id, b.node, 1, false, {}});
      ++created;
    }
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      b.node->split = true;
      b.node->pending += created;
    }
    for (std::size_t s = 0; s + 1 < shares.size(); ++s) {
      if (children[s] == nullptr) continue;
      auto fork = std::make_shared<Branch>(Branch{b.sims,
                                                  std::move(shares[s].region),
                                                  b.choices,
                                                  std::move(children[s]),
                                                  std::nullopt,
                                                  std::nullopt,
                                                  std::nullopt,
                                                  {},
                                                  std::nullopt});
      fork->choices.push_back(shares[s].candidate);
      if (b.open) fork->open = open_slot(b.open->bound);
      const int candidate = shares[s].candidate;
      if (by_bound()) {
        wait(Waiting{std::move(fork), candidate, instance});
        continue;
      }
      tasks_.run([this, fork, candidate, instance] {
        step(fork->sims[instance], candidate);
        explore(std::move(*fork));
      });
    }
    release(b.node);
    if (children.back() == nullptr) {
      close_slot(b);
      return false;
    }
    WeightGrid::Share& last = shares.back();
    b.choices.push_back(last.candidate);
    b.node = std::move(children.back());
    b.region = std::move(last.region);
    b.box.reset();
    b.vectors.reset();
    b.directions.reset();
    b.tied = {};
    if (!by_bound()) return true;
    wait(Waiting{std::make_shared<Branch>(std::move(b)), last.candidate, instance});
    return false;
  }

  [[nodiscard]] ExactSearchStats stats() const {
    ExactSearchStats s;
    s.behaviours = behaviours_.load();
    s.splits = splits_.load();
    s.forks = forks_.load();
    s.steps = steps_.load();
    s.pruned_regions = pruned_regions_.load();
    s.pruned_vectors = pruned_vectors_.load();
    s.smallest_pruned_bound = smallest_pruned_bound_.load();
    s.best = best_.load();
    s.stopped = stopped_.load();
    const std::lock_guard<std::mutex> lock(mutex_);
    s.unresolved_bound = open_bounds_.lowest();
    s.unresolved_branches = open_bounds_.size();
    s.probes = probes_;
    s.best_probe = best_probe_.load();
    return s;
  }

  /// Runs the probes of `bnb` inside `region` alone on every instance, each from a copy of the
  /// instance's unstarted run in `roots` (as tasks, one per probe; waits for them), and lowers the
  /// best objective to theirs.
  void probe(std::span<const Simulation> roots, const WeightRegion& region) {
    if (bnb_ == nullptr) return;
    for (const auto& at : bnb_->probes) {
      if (!grid_.contains(region, at)) continue;
      ++probes_;
      tasks_.run([this, roots, at] {
        const std::vector<double> weights = grid_.weights_at(at);
        std::vector<RunResult> results;
        for (const Simulation& root : roots) {
          Simulation sim = root;
          sim.set_weights(weights);
          while (sim.step()) {
            if (stopping()) return;
          }
          results.push_back(std::move(sim).result());
        }
        const double objective = bnb_->objective(results);
        if (!std::isnan(objective)) {
          lower_to(best_, objective);
          lower_to(best_probe_, objective);
        }
        if (bnb_->on_probe) {
          const std::lock_guard<std::mutex> lock(mutex_);
          bnb_->on_probe(at, objective);
        }
      });
    }
    tasks_.wait();
  }

  /// Branch and bound: a slot among the open bounds for a new branch whose bound is `bound`.
  OpenSlot open_slot(double bound) {
    const std::lock_guard<std::mutex> lock(mutex_);
    return OpenSlot{open_bounds_.open(bound), bound};
  }

  /// Branch and bound: calls bnb->on_anytime once the root's branch is open, so that the curve
  /// of a search starts where it starts (after its probes; a resumed one with its incumbent).
  void report_start() {
    if (bnb_ == nullptr || !bnb_->on_anytime) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    last_report_ = std::chrono::steady_clock::now();
    bnb_->on_anytime(anytime_state());
  }

 private:
  /// A branch waiting for a thread (SearchOrder::Bound): its choice at `instance`'s decision is
  /// not yet stepped.
  struct Waiting {
    std::shared_ptr<Branch> branch;
    int candidate = 0;
    std::size_t instance = 0;
  };

  /// True when branches wait in order of their bounds (SearchOrder::Bound).
  [[nodiscard]] bool by_bound() const { return bnb_ != nullptr && bnb_->order == SearchOrder::Bound; }

  /// Puts `w` among the waiting branches, by its bound, and a task that will take one.
  void wait(Waiting w) {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      const double bound = w.branch->open ? w.branch->open->bound : -std::numeric_limits<double>::infinity();
      waiting_.emplace(bound, std::move(w));
    }
    tasks_.run([this] { take_waiting(); });
  }

  /// Explores the waiting branch of the smallest bound, or of the largest while more than
  /// max_open wait.
  void take_waiting() {
    Waiting w;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      auto at = waiting_.size() > bnb_->max_open ? std::prev(waiting_.end()) : waiting_.begin();
      w = std::move(at->second);
      waiting_.erase(at);
    }
    if (stopping()) return;  // its slot stays open: unresolved
    step(w.branch->sims[w.instance], w.candidate);
    explore(std::move(*w.branch));
  }

  /// True (and remembered) once the caller's stop flag is set.
  bool stopping() {
    if (stop_ == nullptr || !stop_->load(std::memory_order_relaxed)) return false;
    stopped_.store(true, std::memory_order_relaxed);
    return true;
  }

  /// Branch and bound: true (and counted) when `b`'s lower bound exceeds the best objective found.
  bool pruned(Branch& b) {
    if (bnb_ == nullptr) return false;
    const double bound = bnb_->lower_bound(b.sims);
    if (!(bound > best_.load()) || above_journaled(b.node->id)) {
      raise_slot(b, bound);
      return false;
    }
    pruned_regions_.fetch_add(1, std::memory_order_relaxed);
    pruned_vectors_.fetch_add(*b.vectors, std::memory_order_relaxed);
    lower_to(smallest_pruned_bound_, bound);
    if (bnb_->on_pruned) bnb_->on_pruned(*b.vectors);
    SubtreeTally leaf;
    leaf.vectors = *b.vectors;
    leaf.pruned_regions = 1;
    leaf.pruned_vectors = *b.vectors;
    leaf.smallest_pruned_bound = bound;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      b.node->tally.add(leaf);
      if (bnb_->on_leaf) {
        CertifiedLeaf certified;
        certified.region = &b.region;
        certified.choices = b.choices;
        certified.vectors = *b.vectors;
        certified.value = bound;
        for (const Simulation& s : b.sims) certified.steps.push_back(s.steps_taken());
        bnb_->on_leaf(certified);
      }
    }
    close_slot(b);
    release(b.node);
    return true;
  }

  /// True when the journal holds a finished subtree below node `id` (SubtreeJournal::ancestors).
  [[nodiscard]] bool above_journaled(std::uint64_t id) const {
    return journal_ != nullptr && journal_->ancestors != nullptr && journal_->ancestors->contains(id);
  }

  /// The open bounds' share of AnytimeState (under the mutex).
  [[nodiscard]] AnytimeState anytime_state() const {
    AnytimeState s;
    s.best = best_.load();
    s.lower = std::min(s.best, open_bounds_.lowest());
    s.open_branches = open_bounds_.size();
    return s;
  }

  /// Raises `b`'s open bound to `bound` when it grew by more than a thousandth (a lagging bound
  /// is still a bound: each branch's bound only grows as its runs go on), then reports the
  /// state if it is time to.
  void raise_slot(Branch& b, double bound) {
    if (!b.open || !(bound > b.open->bound)) return;
    if (!(bound - b.open->bound > 1e-3 * std::abs(bound)) && std::isfinite(b.open->bound)) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    b.open->slot = open_bounds_.raise(b.open->slot, bound);
    b.open->bound = bound;
    maybe_report();
  }

  /// Takes `b`'s bound off the open ones: it is resolved.
  void close_slot(Branch& b) {
    if (!b.open) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    open_bounds_.close(b.open->slot);
    b.open.reset();
    maybe_report();
  }

  /// Calls bnb->on_anytime when anytime_interval_s has passed since the last call (under the
  /// mutex).
  void maybe_report() {
    if (!bnb_->on_anytime) return;
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - last_report_).count() < bnb_->anytime_interval_s) return;
    last_report_ = now;
    bnb_->on_anytime(anytime_state());
  }

  /// Ends one unfinished part of `node` (its own stretch, or a child's subtree). A node left with
  /// none is finished: the journal learns of it (if it split: a leaf is journaled as its
  /// behaviour, or not at all), and its parent of its tally.
  void release(std::shared_ptr<Node> node) {
    const std::lock_guard<std::mutex> lock(mutex_);
    while (node != nullptr && --node->pending == 0) {
      if (node->split && journal_ != nullptr && journal_->on_done) journal_->on_done(node->id, node->tally);
      if (node->parent != nullptr) node->parent->tally.add(node->tally);
      node = node->parent;
    }
  }

  /// value = min(value, v), atomically.
  static void lower_to(std::atomic<double>& value, double v) {
    double seen = value.load();
    while (v < seen && !value.compare_exchange_weak(seen, v)) {
    }
  }

  void finish(Branch b) {
    close_slot(b);
    Behaviour out;
    out.vectors = b.vectors ? *b.vectors : grid_.count(b.region);
    out.representative = grid_.lexmin(b.region);
    out.bounds = grid_.bounds(b.region);
    out.choices = std::move(b.choices);
    out.region = std::move(b.region);
    out.results.reserve(b.sims.size());
    for (Simulation& sim : b.sims) {
      out.trace = mix64(out.trace ^ sim.decision_trace());
      out.results.push_back(std::move(sim).result());
    }
    behaviours_.fetch_add(1, std::memory_order_relaxed);
    SubtreeTally leaf;
    leaf.vectors = out.vectors;
    leaf.behaviours = 1;
    const std::shared_ptr<Node> node = std::move(b.node);
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      node->tally.add(leaf);
    }
    if (bnb_ != nullptr) {
      const double objective = bnb_->objective(out.results);
      if (!std::isnan(objective)) lower_to(best_, objective);
      // No value, or a better behaviour is known: this one is not optimal.
      if (std::isnan(objective) || objective > best_.load()) {
        if (bnb_->on_leaf) {
          CertifiedLeaf certified;
          certified.kind = CertifiedLeaf::Kind::Beaten;
          certified.region = &out.region;
          certified.choices = out.choices;
          certified.vectors = out.vectors;
          certified.value = objective;
          certified.trace = out.trace;
          const std::lock_guard<std::mutex> lock(mutex_);
          bnb_->on_leaf(certified);
        }
        return release(node);
      }
    }
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      on_behaviour_(std::move(out));
    }
    release(node);
  }

  const WeightGrid& grid_;
  tbb::task_group& tasks_;
  const std::function<void(Behaviour&&)>& on_behaviour_;
  mutable std::mutex mutex_;
  OpenBounds open_bounds_;
  std::multimap<double, Waiting> waiting_;  // SearchOrder::Bound: by bound
  std::chrono::steady_clock::time_point last_report_ = std::chrono::steady_clock::now();
  std::atomic<std::uint64_t> behaviours_{0};
  std::atomic<std::uint64_t> splits_{0};
  std::atomic<std::uint64_t> forks_{0};
  std::atomic<std::uint64_t> steps_{0};
  const BranchAndBound* bnb_;
  const SubtreeJournal* journal_;
  const std::atomic<bool>* stop_;
  std::atomic<bool> stopped_{false};
  std::atomic<std::uint64_t> pruned_regions_{0};
  std::atomic<std::uint64_t> pruned_vectors_{0};
  std::atomic<double> smallest_pruned_bound_{std::numeric_limits<double>::infinity()};
  std::atomic<double> best_{std::numeric_limits<double>::infinity()};
  std::size_t probes_ = 0;
  std::atomic<double> best_probe_{std::numeric_limits<double>::infinity()};
};

}  // namespace

void SubtreeTally::add(const SubtreeTally& other) {
  vectors += other.vectors;
  behaviours += other.behaviours;
  pruned_regions += other.pruned_regions;
  pruned_vectors += other.pruned_vectors;
  smallest_pruned_bound = std::min(smallest_pruned_bound, other.smallest_pruned_bound);
}

std::uint64_t subtree_root(const WeightRegion& root) {
  std::uint64_t h = mix64(0x5EA5C4);
  const auto take = [&](std::uint64_t v) { h = mix64(h ^ v); };
  for (const WeightRegion::Box& box : root.whole) {
    for (std::size_t k = 0; k < box.lo.size(); ++k) {
      take(box.lo[k]);
      take(box.hi[k]);
    }
  }
  for (const WeightRegion::Part& part : root.parts) {
    take(part.block);
    for (const std::uint64_t word : part.bits) take(word);
  }
  return h;
}

std::uint64_t subtree_child(std::uint64_t parent, int choice) {
  return mix64(parent ^ mix64(static_cast<std::uint64_t>(choice) + 1));
}

std::uint64_t subtree_of(std::uint64_t root, std::span<const int> choices) {
  for (const int c : choices) root = subtree_child(root, c);
  return root;
}

std::unordered_set<std::uint64_t> journal_ancestors(std::uint64_t root,
                                                    std::span<const std::vector<int>> choices) {
  std::unordered_set<std::uint64_t> out;
  for (const std::vector<int>& path : choices) {
    std::uint64_t id = root;
    for (const int c : path) {
      out.insert(id);
      id = subtree_child(id, c);
    }
  }
  return out;
}

JournalTop journal_topmost(std::uint64_t root, std::span<const std::vector<int>> choices,
                           const std::unordered_map<std::uint64_t, SubtreeTally>& done) {
  JournalTop out;
  for (const std::vector<int>& path : choices) {
    std::uint64_t id = root;
    std::size_t depth = 0;
    while (!done.contains(id) && depth < path.size()) id = subtree_child(id, path[depth++]);
    const auto it = done.find(id);
    if (it != done.end() && out.ids.insert(id).second) out.vectors += it->second.vectors;
  }
  return out;
}

std::vector<std::array<int, WeightGrid::kMaxWeights>> spread_probes(const WeightGrid& grid,
                                                                    const WeightRegion& region,
                                                                    std::size_t count, std::uint64_t seed) {
  using Point = std::array<int, WeightGrid::kMaxWeights>;
  std::vector<Point> out;
  const auto take = [&](const Point& p) {
    if (out.size() < count && grid.contains(region, p) && std::find(out.begin(), out.end(), p) == out.end())
      out.push_back(p);
  };
  Point middle{};
  for (int k = 0; k < grid.weights(); ++k)
    middle[static_cast<std::size_t>(k)] = static_cast<int>(grid.values(k).size() / 2);
  take(middle);
  Rng rng(mix64(seed ^ 0x9B0BE5));
  for (std::size_t tries = 0; tries < 64 * count && out.size() < count; ++tries) {
    Point p{};
    for (int k = 0; k < grid.weights(); ++k)
      p[static_cast<std::size_t>(k)] = static_cast<int>(uniform_below(rng, grid.values(k).size()));
    take(p);
  }
  return out;
}

ExactSearchStats exact_search(std::span<const RunSpec> instances, const WeightGrid& grid, int threads,
                              const std::function<void(Behaviour&&)>& on_behaviour, const BranchAndBound* bnb,
                              const WeightRegion* within, const SubtreeJournal* journal,
                              const std::atomic<bool>* stop) {
  if (threads < 1) throw std::invalid_argument("exact_search: threads must be >= 1");
  if (instances.empty()) throw std::invalid_argument("exact_search: no instance to search");
  std::vector<Simulation> roots;
  roots.reserve(instances.size());
  for (const RunSpec& spec : instances) {
    roots.emplace_back(spec).keep_sight();  // every branch and probe scans this map again
    // The strategy must score the grid's weights, each of the grid's values allowed.
    const std::unique_ptr<Strategy> probe = spec.strategy.make(spec.seed);
    LinearScoredStrategy* linear = probe->linear_scored();
    if (linear == nullptr) {
      throw std::invalid_argument("exact_search: strategy " + spec.strategy.name + " is not linear-scored");
    }
    if (linear->weights().size() != static_cast<std::size_t>(grid.weights())) {
      throw std::invalid_argument("exact_search: strategy " + spec.strategy.name + " has " +
                                  std::to_string(linear->weights().size()) + " weights, the grid " +
                                  std::to_string(grid.weights()));
    }
    std::vector<double> lowest;
    std::vector<double> highest;
    for (int k = 0; k < grid.weights(); ++k) {
      lowest.push_back(grid.values(k).front());
      highest.push_back(grid.values(k).back());
    }
    linear->set_weights(lowest);  // throws std::invalid_argument naming a weight out of range
    linear->set_weights(highest);
  }
  ExactSearchStats stats;
  // Up to `threads` workers: the global limit as well, since task_group tasks may otherwise
  // run on the default arena's workers (as sweep_runner.cpp does).
  const tbb::global_control allow(tbb::global_control::max_allowed_parallelism,
                                  static_cast<std::size_t>(threads));
  tbb::task_arena arena(threads);
  arena.execute([&] {
    tbb::task_group tasks;
    Explorer explorer(grid, tasks, on_behaviour, bnb, journal, stop);
    // A shard: the root's region is a part of the grid, and so every share.
    WeightRegion everything = within != nullptr ? *within : grid.everything();
    const std::uint64_t root = subtree_root(everything);
    if (!everything.empty() && !explorer.skipped(root, nullptr)) {
      explorer.probe(roots, everything);
      auto first = std::make_shared<Branch>(Branch{std::move(roots),
                                                   std::move(everything),
                                                   {},
                                                   std::make_shared<Node>(Node{root, nullptr, 1, false, {}}),
                                                   std::nullopt,
                                                   std::nullopt,
                                                   std::nullopt,
                                                   {},
                                                   std::nullopt});
      if (bnb != nullptr) first->open = explorer.open_slot(bnb->lower_bound(first->sims));
      explorer.report_start();
      tasks.run([&explorer, first] { explorer.explore(std::move(*first)); });
    }
    tasks.wait();
    stats = explorer.stats();
  });
  return stats;
}

}  // namespace weightsearch
}  // namespace fsweep
