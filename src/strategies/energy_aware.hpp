#pragma once
/// @file energy_aware.hpp
/// Energy-aware exploration, Rappaport 2016 section 3.2 and Algorithm 1; and closest-frontier
/// exploration (Yamauchi 1997) as its weight vector (1, 0, 0, 0).

#include <array>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "core/params.hpp"
#include "strategies/strategy.hpp"

namespace fsweep {
inline namespace strategies {

/// Parameters (JSON keys as named). Weights are in [0, 250] (the paper's search range).
struct EnergyAwareParams {
  double w1 = 10.0;  ///< weight of d_g, robot -> frontier distance
  double w2 = 0.0;   ///< weight of d_gb, frontier -> dock distance
  double w3 = 9.0;   ///< weight of d_gbe, +-d_gb by state of charge (eq. 9)
  double w4 = 20.0;  ///< weight of theta_rel in [0, 1] (eq. 10)
  /// "path": d_g and d_gb are shortest path lengths over known free space (the paper's A*);
  /// "octile": the 8-connected length without obstacles (exact in free space, no search; a
  /// lower bound elsewhere);
  /// "euclidean": straight-line distances between cell centres (the paper in free space; on
  /// this 8-connected grid it underestimates travel by up to 8%, so a battery-limited robot
  /// can run out on the way back: such runs end as battery_depleted).
  std::string distance = "path";
  /// The unit of d_g, d_gb and d_gbe in the cost (eq. 8): "m" (metres) or "cell" (metres /
  /// the map's resolution). The paper does not say; theta_rel is in [0, 1] either way, so on
  /// 10 m cells w4 weighs ten times more against the distances in cells than in metres. Eq. 7
  /// compares metres in both.
  std::string unit = "m";
  /// The goals: "cluster" (each frontier cluster's representative, the paper's p_f) or "cell"
  /// (every frontier cell of the clusters, each its own candidate). Not a parameter of
  /// energy_aware: closest_frontier's `goal` sets it.
  std::string goal = "cluster";

  static constexpr double kMaxWeight = 250.0;
};

/// The declared parameters (core/params.hpp): w1..w4 in [0, 250], distance, unit (recorded
/// only when set, so runs without it keep their run keys).
[[nodiscard]] ParamDecl<EnergyAwareParams> energy_aware_params();

/// closest_frontier's parameters: energy_aware with weights (1, 0, 0, 0) and its distance mode.
struct ClosestFrontierParams {
  std::string distance = "path";  ///< as EnergyAwareParams::distance
  /// "cluster" (default): the representative of the nearest cluster; "cell": the nearest
  /// frontier cell (Holz 2010 eq. 2). Recorded only when set.
  std::string goal = "cluster";
};
[[nodiscard]] ParamDecl<ClosestFrontierParams> closest_frontier_params();

/// The energy-aware strategy. For every frontier cluster representative p_f (the cluster
/// stands for its adjacent frontier cells, split at the sensor range as in section 3.3):
/// 1. d_g = dist(robot, p_f), d_gb = dist(p_f, dock); keep p_f only if d_l > d_g + d_gb (eq. 7),
///    with d_l the remaining range (eq. 5, BatteryView::remaining_range_m);
/// 2. d_gbe = -d_gb while E_l > 0.5 E_t, else +d_gb (eq. 9); an unlimited battery counts as full;
/// 3. theta_rel = (pi - ||theta_r - theta_g| - pi|) / pi (eq. 10), theta_r the direction from the
///    previous decision position to the robot (atan2 of (0,0) = 0 at the first decision, as in
///    Algorithm 1), theta_g the direction from the robot to p_f;
/// 4. choose argmin w1 d_g + w2 d_gb + w3 d_gbe + w4 theta_rel (ties: lowest cluster index).
/// With no candidate: at the dock, finish; elsewhere return to the dock (Algorithm 1). With an
/// unlimited battery there is nothing to return for, so it finishes directly.
/// decide() makes exactly candidates()' choice but, with path distances, stops the search from
/// the robot as soon as no representative it has not reached can win: d_g is at least the
/// search radius and the oracle's lower bound (octile length, triangle through the dock), which
/// bound its cost and eq. 7 (issue 14; the weight search reads candidates() in full).
/// True when one of two shortest octile paths from `from` to `to` (every diagonal step first,
/// or every straight step first) runs over known free cells only, each diagonal step with both
/// cells beside it known free. Such a path is valid with or without corner cutting, and no path
/// is shorter than the octile length, so that length (octile_distance) is then the shortest
/// path length over known free space. O(octile length).
[[nodiscard]] bool octile_path_known_free(const KnownMap& known, Cell from, Cell to);

class EnergyAware final : public LinearScoredStrategy {
 public:
  /// `name` is the registry name ("energy_aware" or "closest_frontier").
  EnergyAware(std::string name, const EnergyAwareParams& params);

  [[nodiscard]] std::string name() const override { return name_; }
  /// With goal "cell" these three see every frontier cell of obs.clusters as its own cluster
  /// (ascending index, so ties go to the lowest cell index).
  [[nodiscard]] Decision decide(const Observation& obs) override;
  [[nodiscard]] Candidates candidates(const Observation& obs) override;
  /// With path distances, the representatives are first measured without a search, in the
  /// order in which they most likely close the others (a known free path of octile length makes
  /// that length exact: octile_path_known_free), until every other one loses at its lower bound;
  /// only when one that may still win has no such path does a search from the robot finish the
  /// choice. It stops once no representative it has not reached can win anywhere in the weight
  /// box (its lowest cost there, at its distance bound, above the highest cost there of one
  /// reached), as decide() does for one weight vector. Which losing representatives are kept
  /// depends on the way taken; the argmin at every vector of the box does not.
  [[nodiscard]] Candidates candidates_within(const Observation& obs, const WeightBounds& bounds) override;
  [[nodiscard]] std::span<const double> weights() const override { return weights_; }
  [[nodiscard]] std::vector<std::string> weight_names() const override { return {"w1", "w2", "w3", "w4"}; }
  void set_weights(std::span<const double> weights) override;
  [[nodiscard]] Decision on_no_candidate(const Observation& obs) override;
  [[nodiscard]] std::unique_ptr<Strategy> clone() const override {
    return std::make_unique<EnergyAware>(*this);
  }
  [[nodiscard]] const EnergyAwareParams& params() const { return params_; }

  /// Feature order of candidates(): d_g (m), d_gb (m), d_gbe (m), theta_rel (1).
  static constexpr int kFeatures = 4;

  /// One decision's terms other than d_g (energy_aware.cpp).
  struct Terms;

 private:
  /// The terms of the decision `obs` (dock distances searched as the distance mode says).
  /// `dock_weighted`: some weight vector asked about weighs d_gb or d_gbe (w2 or w3 > 0); without
  /// it and without a battery limit, path dock distances are not searched and read 0.
  [[nodiscard]] Terms terms(const Observation& obs, bool dock_weighted) const;
  /// terms() for this strategy's own weights.
  [[nodiscard]] Terms own_terms(const Observation& obs) const;
  /// decide(), candidates() and candidates_within() over obs.clusters as given.
  [[nodiscard]] Decision decide_among(const Observation& obs);
  [[nodiscard]] Candidates candidates_among(const Observation& obs);
  [[nodiscard]] Candidates candidates_within_among(const Observation& obs, const WeightBounds& bounds);

  std::string name_;
  EnergyAwareParams params_;
  std::array<double, 4> weights_{};
};

}  // namespace strategies
}  // namespace fsweep
