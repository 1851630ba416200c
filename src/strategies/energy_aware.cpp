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

EnergyAwareParams energy_aware_params_from_json(const nlohmann::json& j, const std::string& where) {
  EnergyAwareParams p;
  if (j.is_null()) return p;
  require_known_keys(j, {"w1", "w2", "w3", "w4", "distance"}, where);
  std::string problems;
  auto weight = [&](const char* key, double& out) {
    if (!j.contains(key)) return;
    const auto& v = j.at(key);
    if (!v.is_number() || v.get<double>() < 0.0 || v.get<double>() > EnergyAwareParams::kMaxWeight) {
      problems += (problems.empty() ? "" : "; ") + where + "/" + key + ": value " + v.dump() +
                  " out of range; allowed: a number in [0, 250]";
      return;
    }
    out = v.get<double>();
  };
  weight("w1", p.w1);
  weight("w2", p.w2);
  weight("w3", p.w3);
  weight("w4", p.w4);
  if (j.contains("distance")) {
    const auto& v = j.at("distance");
    const bool known_mode =
        v.is_string() && (v.get<std::string>() == "path" || v.get<std::string>() == "octile" ||
                          v.get<std::string>() == "euclidean");
    if (!known_mode) {
      problems += (problems.empty() ? "" : "; ") + where + "/distance: value " + v.dump() +
                  " not allowed; allowed: \"path\", \"octile\", \"euclidean\"";
    } else {
      p.distance = v.get<std::string>();
    }
  }
  if (!problems.empty()) throw ConfigError("", problems);
  return p;
}

void to_json(nlohmann::json& j, const EnergyAwareParams& p) {
  j = nlohmann::json{{"w1", p.w1}, {"w2", p.w2}, {"w3", p.w3}, {"w4", p.w4}, {"distance", p.distance}};
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
    // Both legs must be shorter than d_l, so d_l bounds both searches (DESIGN.md section 4).
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
