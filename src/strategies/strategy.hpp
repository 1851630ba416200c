#pragma once
/// @file strategy.hpp
/// The strategy plugin edge: an Observation in, a Decision out.

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/random.hpp"
#include "search/distance_field.hpp"
#include "world/frontiers.hpp"
#include "world/grid.hpp"
#include "world/known_map.hpp"
#include "world/sensor.hpp"

namespace fsweep {
inline namespace strategies {

/// Path-length queries over known free space, answered by the engine (strategies never call
/// planners). Results are in metres; +infinity when unreachable or beyond the bound.
class DistanceOracle {
 public:
  virtual ~DistanceOracle() = default;
  /// Distances from the robot to every cell within `bound_m`.
  [[nodiscard]] virtual std::vector<double> from_robot(std::span<const int> cells, double bound_m) = 0;
  /// Distances from the dock to every cell within `bound_m`.
  [[nodiscard]] virtual std::vector<double> from_dock(std::span<const int> cells, double bound_m) = 0;
  /// Index into `cells` of the nearest cell by path length from the robot (ties: lowest
  /// position in `cells`), or -1 when none is reachable. Stops the search early.
  [[nodiscard]] virtual int nearest_from_robot(std::span<const int> cells) = 0;
  /// Reports `cells` to `watcher` in order of path length from the robot, each with the
  /// distance from_robot(cells, bound_m) would give (cells beyond the bound or unreachable are
  /// not reported), and lets the watcher stop the search once it has what it needs
  /// (search/distance_field.hpp). The default answers from from_robot() and never stops early.
  virtual void watch_from_robot(std::span<const int> cells, double bound_m, SettleWatcher& watcher);
  /// The path length from the robot to `cell` exactly as from_robot({cell}, bound_m) gives it,
  /// by a search that settles at most `max_expansions` cells (a point-to-point search, e.g. A*);
  /// nullopt when that budget ran out first. The default asks from_robot().
  [[nodiscard]] virtual std::optional<double> probe_from_robot(int cell, double bound_m, long max_expansions);
  /// Per cell, a lower bound (metres) of the path length from the robot to it (+infinity: it
  /// is unreachable), known without a search from the robot. The default knows nothing: 0.
  [[nodiscard]] virtual std::vector<double> lower_bounds_from_robot(std::span<const int> cells) const {
    return std::vector<double>(cells.size(), 0.0);
  }
};

/// Battery as the strategy sees it.
struct BatteryView {
  /// Current charge and capacity, in the energy model's unit. Unlimited: both +infinity.
  double level = std::numeric_limits<double>::infinity();
  double capacity = std::numeric_limits<double>::infinity();
  /// Distance (metres) the robot can still travel: Rappaport eq. 5, d_l = E_l / P_m * v_avg,
  /// computed by the engine as level / (energy per metre so far). +infinity when unlimited.
  double remaining_range_m = std::numeric_limits<double>::infinity();
  [[nodiscard]] bool unlimited() const { return capacity == std::numeric_limits<double>::infinity(); }
};

/// Everything a strategy may look at. The references stay valid for one decide() call.
struct Observation {
  const KnownMap& known;
  const FrontierMap& frontiers;
  /// Frontier clusters of this decision (split to the configured maximum length).
  const std::vector<FrontierCluster>& clusters;
  DistanceOracle& distances;
  const SensorParams& sensor;
  Cell robot;
  /// Current heading 0..7 (grid.hpp).
  int heading = 0;
  /// Where the robot was at the previous decision (the start at the first decision).
  Cell previous_position;
  /// The previous decision's goal, if any.
  std::optional<Cell> previous_goal;
  Cell dock;
  BatteryView battery;
  /// Decisions made so far in this run.
  int decision_index = 0;
  /// Set by the engine when the `seg` heuristic (src/sim/heuristics.hpp) restricts this
  /// decision: one flag per cell index of `known`, 1 for the cells of the robot's current map
  /// segment (src/world/segmentation.hpp), 0 elsewhere. `clusters` then holds only the
  /// clusters whose representative lies in that segment; a strategy that reads frontier cells
  /// in another way must keep to the flagged ones too (restrict_to_segment() in
  /// heuristics.hpp). Null when nothing is restricted: `seg` off, or no cluster
  /// representative in the segment.
  const std::vector<std::uint8_t>* segment_mask = nullptr;
};

/// What to do next.
struct Decision {
  enum class Kind { GoTo, ReturnToDock, Finish };
  /// Why a Finish ends the run. Explored: the engine checks for reachable frontiers left
  /// (complete, range_limited or stuck). The other two are for navigation strategies
  /// (target_seeking.hpp) and end the run as `target_reached` / `target_unreachable`.
  enum class Outcome { Explored, TargetReached, TargetUnreachable };
  Kind kind = Kind::Finish;
  /// The goal cell for GoTo.
  Cell goal{};
  /// GoTo: travel at most this many cell steps toward `goal`, then decide again (a strategy
  /// that re-evaluates its choice after every step sets 1). 0: travel all the way. For the
  /// engine's stuck rule a journey cut short by this limit is not a quiet decision unless
  /// the robot did not move (simulation.hpp).
  int max_steps = 0;
  /// Finish: why (see Outcome), with free text for the run's end_detail.
  Outcome outcome = Outcome::Explored;
  std::string detail;
  static Decision go_to(Cell c) {
    Decision d;
    d.kind = Kind::GoTo;
    d.goal = c;
    return d;
  }
  static Decision return_to_dock() {
    Decision d;
    d.kind = Kind::ReturnToDock;
    return d;
  }
  static Decision finish() { return Decision{}; }
  /// GoTo `c`, deciding again after at most `steps` cell steps (>= 1).
  static Decision go_toward(Cell c, int steps) {
    Decision d = go_to(c);
    d.max_steps = steps;
    return d;
  }
  /// Finish with a navigation outcome and its detail text.
  static Decision finish_with(Outcome outcome, std::string detail) {
    Decision d = finish();
    d.outcome = outcome;
    d.detail = std::move(detail);
    return d;
  }
};

/// Candidates of a linear-scored strategy: cost(i) = sum_k weights[k] * features[i*K + k].
struct Candidates {
  std::vector<Cell> cells;
  /// Row-major, cells.size() x feature_count.
  std::vector<double> features;
  int feature_count = 0;
};

/// weights . features, summed in feature order from 0.0: the cost argmin_linear compares. It
/// never decreases when a feature with a non-negative weight grows, so a lower bound of a
/// feature gives a lower bound of the cost (the energy-aware choice bounds d_g so).
[[nodiscard]] inline double linear_cost(std::span<const double> weights, std::span<const double> features) {
  double cost = 0.0;
  for (std::size_t f = 0; f < features.size(); ++f) cost += weights[f] * features[f];
  return cost;
}

/// Index of argmin_i weights . features_i; ties break to the lowest i. -1 when empty.
[[nodiscard]] int argmin_linear(const Candidates& c, std::span<const double> weights);

/// Where the directions w / (w_1 + ... + w_n) of some weight vectors (each weight >= 0) lie:
/// per weight, in [lo, hi], for each of them but the zero vector. Costs scale with w, so a
/// choice depends on the direction alone, up to rounding. The exact weight search describes its
/// regions so (WeightGrid::directions()); the default describes every vector.
struct WeightDirections {
  static constexpr std::size_t kMaxWeights = 4;
  std::array<double, kMaxWeights> lo{0.0, 0.0, 0.0, 0.0};
  std::array<double, kMaxWeights> hi{1.0, 1.0, 1.0, 1.0};
  /// The vectors include the zero vector, and one other than it.
  bool zero = true;
  bool nonzero = true;
};

/// True when a candidate of features `f_j` costs more than one of features `f_i` (as
/// linear_cost() computes both, so argmin_linear() never chooses the former when the latter is
/// among the candidates) at every weight vector other than zero whose direction lies in
/// `directions`. Proven, without visiting vectors, when
///   w . (f_j - f_i) > 1e-12 * sum_k w_k (|f_jk| + |f_ik|)
/// at every direction w of the box (summing to 1; bounded below by linear-programming duality):
/// the right side bounds the rounding of both costs (linear_cost() sums at most four products
/// from 0.0, off by at most 4.5e-16 * sum_k w_k |f_k| each) with room for the rounding of this
/// test. False when that is not proven, when a feature is not finite, or when there are more
/// than four features. Lower bounds of f_j's features keep it sound (the test only tightens as
/// f_j grows). `extra`: a further margin the left side must exceed, per unit of sum(w) (for a
/// caller whose directions are of other coordinates than w: WeightGrid::sole_choice_tied()).
[[nodiscard]] bool costs_more_at_every_direction(std::span<const double> f_j, std::span<const double> f_i,
                                                 const WeightDirections& directions, double extra = 0.0);

/// The same claim at every weight vector w with lo_k <= w_k <= hi_k (0 <= lo_k <= hi_k, finite):
/// proven when w . (f_j - f_i) > 1e-12 * sum_k w_k (|f_jk| + |f_ik|) at the box's lowest
/// corner for that linear function. Never proven for a box that holds the zero vector (there
/// every cost is 0).
[[nodiscard]] bool costs_more_at_every_weight(std::span<const double> f_j, std::span<const double> f_i,
                                              std::span<const double> lo, std::span<const double> hi);

/// The weight vectors a caller asks about at once: each weight in [lo, hi], with directions in
/// `directions`.
struct WeightBounds {
  std::span<const double> lo;
  std::span<const double> hi;
  WeightDirections directions;
};

class LinearScoredStrategy;

/// A frontier-selection strategy. Instances may keep state between decisions (a seeded
/// generator, the previous goal); clone() copies that state exactly.
class Strategy {
 public:
  virtual ~Strategy() = default;
  [[nodiscard]] virtual std::string name() const = 0;
  [[nodiscard]] virtual Decision decide(const Observation& obs) = 0;
  [[nodiscard]] virtual std::unique_ptr<Strategy> clone() const = 0;
  /// The target cell of a navigation strategy (target_seeking.hpp), for the engine's target
  /// metrics (RunMetrics::target_path_m); none for exploration strategies.
  [[nodiscard]] virtual std::optional<Cell> target() const { return std::nullopt; }
  /// This strategy as a LinearScoredStrategy, or null when it is not one (the registry declares
  /// which are: StrategyTraits::linear_scored).
  [[nodiscard]] virtual LinearScoredStrategy* linear_scored() { return nullptr; }
  [[nodiscard]] virtual const LinearScoredStrategy* linear_scored() const { return nullptr; }
};

/// A strategy whose choice is argmin(weights . features) over candidates. The engine may read
/// candidates() and weights() directly to evaluate many weight vectors at once (docs/dev/architecture.md,
/// "Sweeps, keys, shards and the weight search").
class LinearScoredStrategy : public Strategy {
 public:
  [[nodiscard]] LinearScoredStrategy* linear_scored() final { return this; }
  [[nodiscard]] const LinearScoredStrategy* linear_scored() const final { return this; }
  /// The candidates of this decision, after any feasibility filter.
  [[nodiscard]] virtual Candidates candidates(const Observation& obs) = 0;
  /// The candidates of this decision that argmin_linear() may choose for some weight vector w
  /// of `bounds` (bounds.lo <= w <= bounds.hi, each weight, with its direction in
  /// bounds.directions), in the order of candidates(), with the same features: candidates()
  /// with some of those left out that lose at every such w (cost above another's, or equal and
  /// later), so that argmin_linear() over them chooses the same cell as over candidates() at
  /// every such w. The exact weight search asks this with its region's bounds; a strategy may
  /// compute less for it. The default is candidates().
  [[nodiscard]] virtual Candidates candidates_within(const Observation& obs, const WeightBounds& bounds) {
    (void)bounds;
    return candidates(obs);
  }
  [[nodiscard]] virtual std::span<const double> weights() const = 0;
  /// The parameter name of each weight, in the order of weights() (e.g. "w1".."w4"): a sweep's
  /// exact weight search (sweep_plan.hpp) sweeps these parameters.
  [[nodiscard]] virtual std::vector<std::string> weight_names() const = 0;
  /// Makes the strategy score by `weights` (as many as weights() has, each in its allowed range)
  /// from now on: the exact weight search (weightsearch/exact_search.hpp) lets a simulation whose region
  /// has one weight vector left go on as a run with those weights. Throws std::invalid_argument
  /// for another number of weights or a weight out of its range.
  virtual void set_weights(std::span<const double> weights) = 0;
  /// What to do when no candidate survives.
  [[nodiscard]] virtual Decision on_no_candidate(const Observation& obs) = 0;
  /// The decision of `obs` when it does not depend on the weights, so that no candidates are
  /// scored (target_seeking on its target, or with the target in reach); nullopt (the default):
  /// decide among candidates().
  [[nodiscard]] virtual std::optional<Decision> fixed_decision(const Observation& obs) {
    (void)obs;
    return std::nullopt;
  }
  /// The decision once candidate `cell` (one of candidates().cells) won: by default the whole way
  /// to it; a strategy may travel part of the way (Decision::go_toward).
  [[nodiscard]] virtual Decision choose(const Observation& obs, Cell cell) {
    (void)obs;
    return Decision::go_to(cell);
  }

  /// fixed_decision(), else choose() for argmin_linear() over candidates(), else
  /// on_no_candidate(): the exact weight search (Simulation::choice()) splits at the same place.
  [[nodiscard]] Decision decide(const Observation& obs) override {
    if (std::optional<Decision> fixed = fixed_decision(obs)) return std::move(*fixed);
    const Candidates c = candidates(obs);
    const int best = argmin_linear(c, weights());
    if (best < 0) return on_no_candidate(obs);
    return choose(obs, c.cells[static_cast<std::size_t>(best)]);
  }
};

}  // namespace strategies
}  // namespace fsweep
