#include "strategies/gbl.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <utility>

#include "core/config_error.hpp"
#include "strategies/sensing_region.hpp"

namespace fsweep {
inline namespace strategies {

ScanCounts GainScanner::at(const Observation& obs, Cell p) {
  const double resolution_m = obs.known.resolution_m();
  const SensorParams& s = obs.sensor;
  if (!ready_ || resolution_m != resolution_m_ || s != params_) {
    sensor_ = Sensor(s, resolution_m);
    params_ = s;
    resolution_m_ = resolution_m;
    ready_ = true;
  }
  return sensor_.gain(obs.known, p, scan_heading(obs, p));
}

double GainScanner::scan_heading(const Observation& obs, Cell p) {
  if (p == obs.robot) return heading_angle(obs.heading);
  return std::atan2(static_cast<double>(p.y - obs.robot.y), static_cast<double>(p.x - obs.robot.x));
}

ParamDecl<GblParams> gbl_params() {
  ParamDecl<GblParams> d;
  d.integer("samples", &GblParams::samples, "random draws of candidate locations per decision")
      .range(1, 100000);
  d.number("radius_m", &GblParams::radius_m,
           "candidates are known free cells within this distance of a frontier cell (0: the frontier cell)")
      .at_least(0)
      .unit("m");
  d.number("lambda", &GblParams::lambda, "weight of travel cost in I(p) exp(-lambda L(p)) (Holz 2010 eq. 3)")
      .at_least(0)
      .unit("1/m");
  return d;
}

Gbl::Gbl(const GblParams& params, std::uint64_t seed) : params_(params), rng_(make_rng(seed, "gbl")) {}

std::vector<GblCandidate> Gbl::candidates(const Observation& obs) {
  const KnownMap& known = obs.known;
  // Memory: a previous goal reached by a trip that revealed nothing is fruitless.
  if (obs.previous_goal && *obs.previous_goal == obs.robot && known.known_count() == last_known_count_) {
    const int here = known.index(obs.robot);
    const auto it = std::lower_bound(fruitless_.begin(), fruitless_.end(), here);
    if (it == fruitless_.end() || *it != here) fruitless_.insert(it, here);
  }
  last_known_count_ = known.known_count();

  // 1. The frontier cells the engine offers; with a segment restriction, those in the robot's
  //    segment (all of them when none is).
  std::vector<int> frontier = open_frontier_cells(obs);
  const std::vector<std::uint8_t>* segment = obs.segment_mask;
  if (segment != nullptr) {
    std::vector<int> inside;
    for (const int i : frontier) {
      if ((*segment)[static_cast<std::size_t>(i)] != 0) inside.push_back(i);
    }
    if (inside.empty()) {
      segment = nullptr;
    } else {
      frontier = std::move(inside);
    }
  }
  if (frontier.empty()) return {};

  // 2. Random draws near frontier cells. Neighbourhood offsets in row-major order.
  const double r_cells = params_.radius_m / known.resolution_m();
  const double limit = r_cells * r_cells * (1.0 + 1e-9) + 1e-9;  // inclusive, as the sensor's range
  const int r = static_cast<int>(std::floor(std::sqrt(limit)));
  std::vector<Cell> offsets;
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      if (static_cast<double>(dx * dx + dy * dy) <= limit) offsets.push_back(Cell{dx, dy});
    }
  }
  const int robot_index = known.index(obs.robot);
  std::vector<int> drawn;
  std::vector<int> near;
  near.reserve(offsets.size());
  for (int s = 0; s < params_.samples; ++s) {
    const Cell f = known.cell(frontier[static_cast<std::size_t>(uniform_below(rng_, frontier.size()))]);
    near.clear();
    for (const Cell d : offsets) {
      const Cell c{f.x + d.x, f.y + d.y};
      if (!known.is_free(c)) continue;  // off-map cells count as occupied
      const int i = known.index(c);
      if (i == robot_index || std::binary_search(fruitless_.begin(), fruitless_.end(), i)) continue;
      if (segment != nullptr && (*segment)[static_cast<std::size_t>(i)] == 0) continue;
      near.push_back(i);
    }
    if (near.empty()) continue;
    const int pick = near[static_cast<std::size_t>(uniform_below(rng_, near.size()))];
    if (std::find(drawn.begin(), drawn.end(), pick) == drawn.end()) drawn.push_back(pick);
  }
  if (drawn.empty()) return {};

  // 3. Reachability and path length; 4. information gain.
  const std::vector<double> length = obs.distances.from_robot(drawn, std::numeric_limits<double>::infinity());
  const double cell_area_m2 = known.resolution_m() * known.resolution_m();
  std::vector<GblCandidate> out;
  for (std::size_t k = 0; k < drawn.size(); ++k) {
    if (!std::isfinite(length[k])) continue;
    const Cell p = known.cell(drawn[k]);
    out.push_back(GblCandidate{p, length[k], scanner_.at(obs, p).unknown * cell_area_m2});
  }
  return out;
}

int Gbl::best(const std::vector<GblCandidate>& c, double lambda) {
  int best = -1;
  double best_log_u = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < c.size(); ++k) {
    if (!(c[k].gain_m2 > 0.0)) continue;
    // Equation 3 in log form: log(I e^{-lambda L}) = log I - lambda L.
    const double log_u = std::log(c[k].gain_m2) - lambda * c[k].length_m;
    if (best < 0 || log_u > best_log_u) {  // strict: ties keep the lowest position
      best = static_cast<int>(k);
      best_log_u = log_u;
    }
  }
  return best;
}

Decision Gbl::decide(const Observation& obs) {
  const std::vector<GblCandidate> c = candidates(obs);  // steps 1-4
  const int b = best(c, params_.lambda);                // step 5
  if (b >= 0) return Decision::go_to(c[static_cast<std::size_t>(b)].cell);
  // 6. Fallback: the nearest cluster representative.
  std::vector<int> reps;
  reps.reserve(obs.clusters.size());
  for (const auto& cluster : obs.clusters) reps.push_back(cluster.representative);
  const int nearest = obs.distances.nearest_from_robot(reps);
  if (nearest < 0) return Decision::finish();
  return Decision::go_to(obs.known.cell(reps[static_cast<std::size_t>(nearest)]));
}

}  // namespace strategies
}  // namespace fsweep
