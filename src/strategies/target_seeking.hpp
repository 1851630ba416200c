#pragma once
/// @file target_seeking.hpp
/// Navigation to a known target position through unknown space by exploration principles:
/// Arvanitakis, Giannousakis, Tzes, "Mobile Robot Navigation in Unknown Environment based on
/// Exploration Principles" (papers/arvanitakis-navigation-unknown-environment.txt).
///
/// Reading of the paper (section III-B, equation 12): the chosen frontier is the ARGMIN of
///   w1 / L[frontier] + w2 * Hg(target, frontier) + w3 * Hg(robot, frontier),
/// every term a cost >= 0: a long frontier (large L) lowers the first term, a frontier near
/// the target or near the robot lowers the other two. Distances and lengths are in metres.
/// The cost is linear in (w1, w2, w3) with features (1 / L, Hg(target), Hg(robot)), and is
/// computed so, as linear_cost() (w1 * (1 / L), not w1 / L, which may differ in the last bit):
/// the strategy is linear-scored, so the exact weight search covers it.
/// The choice is re-evaluated after every cell step ("evaluated constantly in conjunction
/// with the control law"). Once the target cell is known free the robot follows the shortest
/// path to it (equation 3, section III-A end).

#include <array>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/params.hpp"
#include "strategies/strategy.hpp"
#include "world/sensor.hpp"
#include "world/world_map.hpp"

namespace fsweep {
inline namespace strategies {

/// How the robot moves toward the chosen frontier.
enum class TargetMotion {
  /// One step along a shortest known-free path to the goal cell of the chosen frontier.
  ShortestPath,
  /// The discrete gradient ascent of equations 2, 10 and 13-15 (gradient_step()).
  Gradient,
};

/// Parameters (JSON keys: "target", "w1", "w2", "w3", "motion").
struct TargetSeekingParams {
  /// The target cell [x, y] (cells, grid.hpp convention). None (JSON null or key absent):
  /// pure exploration, the paper's phi = 1 (section II-B): equation 12 without its target
  /// term, every reachable frontier eligible, Finish (explored) when none is left.
  std::optional<Cell> target;
  /// JSON "target": "random": the simulation draws the target per run (a free cell reachable
  /// from the start on the true map other than the start, uniform, stream "target" of the run
  /// seed; Simulation's constructor) and hands the strategy the resolved [x, y]; `target` is
  /// then empty. TargetSeeking::decide with unresolved params throws ConfigError.
  bool random_target = false;
  /// Equation 12 weights, each in [0, 1]. Defaults: the paper's first scenario (section IV).
  double w1 = 1.0;
  double w2 = 0.9;
  double w3 = 0.4;
  /// "shortest_path" (default) or "gradient".
  TargetMotion motion = TargetMotion::ShortestPath;
};

/// The declared parameters (core/params.hpp). "target" is null, two integers >= 0 (a target
/// outside the map is only known at run time and ends the run as target_unreachable), or
/// "random" (random_target).
[[nodiscard]] ParamDecl<TargetSeekingParams> target_seeking_params();

/// One frontier scored by equation 12.
struct ScoredFrontier {
  /// Member frontier cell indices, ascending.
  std::vector<int> cells;
  /// L: member count times resolution (metres).
  double length_m = 0.0;
  /// Hg(target, frontier) through the target's unknown region (metres; geodesic.hpp).
  double hg_target_m = 0.0;
  /// Hg(robot, frontier) through known free space (metres, from the DistanceOracle).
  double hg_robot_m = 0.0;
  /// Equation 12's features: 1 / L, hg_target_m (0 without a target), hg_robot_m.
  std::array<double, 3> features{};
  /// The goal cell index inside the frontier: the member q with the smallest
  /// d_robot(q) + d_target(q), the estimated length of a route to the target through q (ties:
  /// lowest index; without a target the member nearest the robot).
  int goal = -1;
  /// linear_cost((w1, w2, w3), features): w1 / L + w2 * hg_target_m + w3 * hg_robot_m.
  double score = 0.0;
};

/// The frontier choice of one decision.
struct FrontierChoice {
  /// The eligible frontiers, in the order of their lowest cell index.
  std::vector<ScoredFrontier> frontiers;
  /// Position in `frontiers` of the minimum score (ties: the lowest position); -1 when none.
  int chosen = -1;
  /// The goal of the chosen frontier (ScoredFrontier::goal); -1 when none.
  int goal = -1;
  /// Geodesic distance (metres) from the target to every cell through the region of step 2
  /// (all 0 without a target; empty when the target is off the map or no frontier exists).
  std::vector<double> from_target_m;
};

/// Equation 12 over the frontiers of `obs` for a target cell that is unknown, or free but not
/// reachable through known free space; without a target (pure exploration) the w2 term and
/// the region filter of steps 2-3 are left out and the goal is the member nearest the robot.
/// 1. Frontiers: the frontier cells of obs.clusters (so `seg` and dropped goals apply), merged
///    back into 8-connected groups (frontier_groups(), widest_frontier.hpp), so that L is the
///    length of a whole frontier, not of a piece split at the cluster length limit.
/// 2. The region: the unknown cells and frontier cells (unknown_region(), geodesic.hpp) when
///    the target is unknown; every cell not known occupied when it is known free (the target
///    is then beyond a gap the robot cannot pass in known space). Geodesic distances from the
///    target through it (geodesic_distances()).
/// 3. Eligible: frontiers that border the region containing the target (some member has a
///    finite distance from the target) and that the robot can reach (finite oracle distance).
/// 4. Scored by equation 12 with params' weights; the chosen one is the minimum (ties: the
///    earliest).
[[nodiscard]] FrontierChoice choose_target_frontier(const Observation& obs,
                                                    const TargetSeekingParams& params);

/// Equations 13-15 on the known map, for the chosen frontier A_c (cells `chosen`).
struct ExplorationField {
  /// f(p) * phi(p) per cell: f(p) = 1 / (Hg(p, A_c) + 1) with Hg through known free space (the
  /// paper's A), phi(p) = 1 / (d_g(y, target) + 1) with y the cell of A_c nearest to p
  /// (equation 15; ties as GeodesicField::nearest_source) and d_g(y, target) = from_target_m[y]
  /// (through the target's region, as the paper says). 0 for cells not known free or not
  /// connected to A_c.
  std::vector<double> weight;
  /// Hg(p, A_c) in metres per cell (+infinity where not connected).
  std::vector<double> to_frontier_m;
};

/// Computes the ExplorationField (distances in metres).
[[nodiscard]] ExplorationField exploration_field(const KnownMap& known, std::span<const int> chosen,
                                                 std::span<const double> from_target_m);

/// The known map as a WorldMap for visibility tests: known free cells free, all others occupied.
[[nodiscard]] WorldMap known_as_world(const KnownMap& known);

/// Equation 2 on the grid: H(at) = the sum of `weight` over the known free cells visible from
/// `at` (`at` itself included), visibility by the rules of `sensor` (Sensor::visible(), range
/// included; grid model: field of view ignored, the paper's sensor is omnidirectional; beam
/// model: the beams of a scan facing `heading_rad`, radians as heading_angle()) on `view`
/// (known_as_world()).
[[nodiscard]] double exploration_objective(const WorldMap& view, const Sensor& sensor, Cell at,
                                           double heading_rad, std::span<const double> weight);

/// The discrete gradient step (equations 10-11: u = dH/dr). Candidates: the 8 neighbours of
/// `robot` it can step to under any corner rule (known free; a diagonal also needs both cells
/// beside it known free) that bring it strictly nearer to A_c (field.to_frontier_m). Result:
/// the candidate with the largest exploration_objective() facing the step's heading (ties: the
/// lowest heading, grid.hpp);
/// empty when there is none (the robot is on A_c, or A_c is out of reach).
/// Why the progress condition: our H counts only cells known now, while the continuous law
/// also gains from the cells it is about to sense; pure ascent of the discrete H stops short
/// of the frontier (in a corridor, H is largest where the most near-frontier cells are in view,
/// a few cells before its end) and would stall there. Among progressing moves H still decides,
/// which keeps the robot away from walls (section IV: paths "sufficiently far from the
/// discovered area boundaries").
[[nodiscard]] std::optional<Cell> gradient_step(const KnownMap& known, const Sensor& sensor, Cell robot,
                                                const ExplorationField& field);

/// The `target_seeking` strategy. Every decision:
/// 0. no target: choose_target_frontier(); none eligible: Finish (explored); else GoTo its goal,
///    the whole way, like the other exploration strategies (without a target there is nothing
///    to re-aim at while crossing known space, and a plan per cell step would make sampling
///    planners, which use their whole time budget per query, impractical);
/// 1. target outside the map, or known occupied: Finish, target_unreachable;
/// 2. robot on the target: Finish, target_reached;
/// 3. target known free and reachable through known free space: GoTo the target, the whole
///    way (equation 3: shortest path; the planner of the run plans it);
/// 4. otherwise choose_target_frontier(): none eligible: Finish, target_unreachable (the
///    region of the target has no reachable frontier left, e.g. it is walled in); else one cell
///    step, deciding again after it (Decision::go_toward(cell, 1)): with motion shortest_path
///    toward the choice's goal; with motion gradient to gradient_step() over the
///    exploration_field() of the chosen frontier, or, when that is empty, toward the goal as
///    with shortest_path.
/// Stateless apart from its parameters. Works with any planner, but with a target the engine
/// plans once per cell step: use a grid planner (astar, dijkstra) for navigation runs.
///
/// As a LinearScoredStrategy: steps 1-3 are fixed_decision(); the candidates of step 0 and 4 are
/// the eligible frontiers, each by its goal cell with equation 12's features; choose() turns
/// the winner into the motion of step 0 or 4; on_no_candidate() is the Finish of step 0 or 4.
/// Every member throws ConfigError ("strategy/params/target") when params.random_target is
/// set: a random target must be resolved to a cell by the simulation first.
class TargetSeeking final : public LinearScoredStrategy {
 public:
  explicit TargetSeeking(const TargetSeekingParams& params)
      : params_(params), weights_{params.w1, params.w2, params.w3} {}
  [[nodiscard]] std::string name() const override { return "target_seeking"; }
  [[nodiscard]] std::unique_ptr<Strategy> clone() const override {
    return std::make_unique<TargetSeeking>(*this);
  }
  [[nodiscard]] const TargetSeekingParams& params() const { return params_; }
  [[nodiscard]] std::optional<Cell> target() const override { return params_.target; }

  [[nodiscard]] std::optional<Decision> fixed_decision(const Observation& obs) override;
  [[nodiscard]] Candidates candidates(const Observation& obs) override;
  [[nodiscard]] Decision choose(const Observation& obs, Cell cell) override;
  [[nodiscard]] Decision on_no_candidate(const Observation& obs) override;
  [[nodiscard]] std::span<const double> weights() const override { return weights_; }
  [[nodiscard]] std::vector<std::string> weight_names() const override { return {"w1", "w2", "w3"}; }
  /// w1, w2, w3, each in [0, 1].
  void set_weights(std::span<const double> weights) override;

 private:
  TargetSeekingParams params_;
  std::array<double, 3> weights_;
};

}  // namespace strategies
}  // namespace fsweep
