#include "strategies/energy_aware.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/config_error.hpp"

namespace fsweep {
inline namespace strategies {
namespace {

double direction(Cell from, Cell to) {
  return std::atan2(static_cast<double>(to.y - from.y), static_cast<double>(to.x - from.x));
}

/// Rappaport 2016 eq. 10: relative orientation in [0, 1].
double theta_rel(double theta_r, double theta_g) {
  return (M_PI - std::abs(std::abs(theta_r - theta_g) - M_PI)) / M_PI;
}

}  // namespace

namespace {

const std::vector<std::string> kDistanceModes{"path", "octile", "euclidean"};
constexpr const char* kDistanceDoc =
    "how d_g and d_gb are measured: shortest path over known free space (the paper's A*), "
    "octile length without obstacles, or straight line between cell centres";

}  // namespace

ParamDecl<EnergyAwareParams> energy_aware_params() {
  ParamDecl<EnergyAwareParams> d;
  const double max = EnergyAwareParams::kMaxWeight;
  d.number("w1", &EnergyAwareParams::w1, "weight of d_g, robot to frontier distance (Rappaport 2016 eq. 8)")
      .range(0, max);
  d.number("w2", &EnergyAwareParams::w2, "weight of d_gb, frontier to dock distance (eq. 8)").range(0, max);
  d.number("w3", &EnergyAwareParams::w3, "weight of d_gbe, -d_gb above half charge, +d_gb below (eq. 9)")
      .range(0, max);
  d.number("w4", &EnergyAwareParams::w4, "weight of theta_rel in [0, 1], the turn toward the goal (eq. 10)")
      .range(0, max);
  d.choice("distance", &EnergyAwareParams::distance, kDistanceModes, kDistanceDoc);
  return d;
}

ParamDecl<ClosestFrontierParams> closest_frontier_params() {
  ParamDecl<ClosestFrontierParams> d;
  d.choice("distance", &ClosestFrontierParams::distance, kDistanceModes, kDistanceDoc);
  return d;
}

EnergyAware::EnergyAware(std::string name, const EnergyAwareParams& params)
    : name_(std::move(name)), params_(params), weights_{params.w1, params.w2, params.w3, params.w4} {}

Candidates EnergyAware::candidates(const Observation& obs) {
  Candidates out;
  out.feature_count = kFeatures;
  const auto& clusters = obs.clusters;
  if (clusters.empty()) return out;

  std::vector<int> reps;
  reps.reserve(clusters.size());
  for (const auto& c : clusters) reps.push_back(c.representative);

  const double d_l = obs.battery.remaining_range_m;
  const double res = obs.known.resolution_m();
  std::vector<double> d_g;
  std::vector<double> d_gb;
  if (params_.distance == "euclidean" || params_.distance == "octile") {
    const auto metric = params_.distance == "euclidean" ? &euclidean_distance : &octile_distance;
    d_g.reserve(reps.size());
    d_gb.reserve(reps.size());
    for (const int r : reps) {
      d_g.push_back(metric(obs.robot, obs.known.cell(r)) * res);
      d_gb.push_back(metric(obs.known.cell(r), obs.dock) * res);
    }
  } else {
    // Both legs must be shorter than d_l, so d_l bounds both searches (docs/architecture.md, "Plugins and
    // their parameters").
    d_g = obs.distances.from_robot(reps, d_l);
    // With an unlimited battery d_gb matters only through its weights: skip that search if
    // both are zero (the features then read 0, which those weights ignore).
    const bool need_dock = !obs.battery.unlimited() || weights_[1] != 0.0 || weights_[2] != 0.0;
    d_gb = need_dock ? obs.distances.from_dock(reps, d_l) : std::vector<double>(reps.size(), 0.0);
  }

  // Eq. 9: the sign of d_gbe flips at half charge. An unlimited battery is always "full".
  const bool above_half = obs.battery.unlimited() || obs.battery.level > 0.5 * obs.battery.capacity;
  const double theta_r = direction(obs.previous_position, obs.robot);
  out.cells.reserve(reps.size());
  out.features.reserve(reps.size() * kFeatures);
  for (std::size_t i = 0; i < reps.size(); ++i) {
    if (!std::isfinite(d_g[i]) || !std::isfinite(d_gb[i])) continue;
    if (!(d_l > d_g[i] + d_gb[i])) continue;  // eq. 7, strict
    const Cell f = obs.known.cell(reps[i]);
    out.cells.push_back(f);
    out.features.push_back(d_g[i]);
    out.features.push_back(d_gb[i]);
    out.features.push_back(above_half ? -d_gb[i] : d_gb[i]);
    out.features.push_back(theta_rel(theta_r, direction(obs.robot, f)));
  }
  return out;
}

Decision EnergyAware::decide(const Observation& obs) {
  // Fast path for pure closest-frontier with no battery limit: the same argmin (nearest by
  // path, ties to the lowest cluster index) found by one early-stopping search.
  const bool pure_distance =
      weights_[1] == 0.0 && weights_[2] == 0.0 && weights_[3] == 0.0 && weights_[0] > 0.0;
  if (pure_distance && obs.battery.unlimited() && params_.distance == "path") {
    std::vector<int> reps;
    reps.reserve(obs.clusters.size());
    for (const auto& c : obs.clusters) reps.push_back(c.representative);
    const int best = obs.distances.nearest_from_robot(reps);
    if (best < 0) return on_no_candidate(obs);
    return Decision::go_to(obs.known.cell(reps[static_cast<std::size_t>(best)]));
  }
  return LinearScoredStrategy::decide(obs);
}

Decision EnergyAware::on_no_candidate(const Observation& obs) {
  if (obs.battery.unlimited() || obs.robot == obs.dock) return Decision::finish();
  return Decision::return_to_dock();
}

}  // namespace strategies
}  // namespace fsweep
