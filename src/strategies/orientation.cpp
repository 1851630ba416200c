#include "strategies/orientation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "core/config_error.hpp"
#include "strategies/sensing_region.hpp"

namespace fsweep {
inline namespace strategies {

ParamDecl<OrientationParams> orientation_params() {
  ParamDecl<OrientationParams> d;
  d.number("head_distance_ratio", &OrientationParams::head_distance_ratio,
           "the walk along the clockwise list stops before the first cell at least this times d_s from "
           "the list head (Mei 2006 section IV-B step 3(b))")
      .range(0, 1)
      .above(0);
  declare_sensing_region_params(d);
  return d;
}

std::vector<int> clockwise_from_left(const KnownMap& known, Cell robot, int heading,
                                     std::span<const int> cells) {
  struct Keyed {
    double angle;
    double distance;
    int index;
  };
  const double left = heading_angle(heading) - M_PI / 2.0;
  std::vector<Keyed> keyed;
  keyed.reserve(cells.size());
  for (const int i : cells) {
    const Cell c = known.cell(i);
    if (c == robot) continue;
    const double dx = c.x - robot.x;
    const double dy = c.y - robot.y;
    // Clockwise on screen (y down) is increasing atan2(dy, dx) (grid.hpp).
    double a = std::atan2(dy, dx) - left;
    a = std::fmod(a, 2.0 * M_PI);
    if (a < 0.0) a += 2.0 * M_PI;
    if (a >= 2.0 * M_PI - 1e-12) a = 0.0;  // the left itself, after rounding
    keyed.push_back({a, std::hypot(dx, dy), i});
  }
  std::sort(keyed.begin(), keyed.end(), [](const Keyed& a, const Keyed& b) {
    if (std::abs(a.angle - b.angle) > 1e-12) return a.angle < b.angle;
    if (a.distance != b.distance) return a.distance < b.distance;
    return a.index < b.index;
  });
  std::vector<int> out;
  out.reserve(keyed.size());
  for (const auto& k : keyed) out.push_back(k.index);
  return out;
}

std::size_t walk_from_head(const KnownMap& known, std::span<const int> ordered, double limit_cells) {
  const Cell head = known.cell(ordered.front());
  std::size_t at = 0;
  while (at + 1 < ordered.size()) {
    const Cell cur = known.cell(ordered[at]);
    const Cell next = known.cell(ordered[at + 1]);
    const bool neighbours = std::max(std::abs(next.x - cur.x), std::abs(next.y - cur.y)) == 1;  // (a)
    if (!neighbours || !(euclidean_distance(head, next) < limit_cells)) break;                  // (b)
    ++at;
  }
  return at;
}

Decision Orientation::decide(const Observation& obs) {
  SensingRegion region = split_by_sensing_region(obs, params_);  // step 1
  restrict_to_segment(obs, region);  // the `seg` heuristic, when on (src/sim/heuristics.hpp)
  if (region.inside.empty()) return closest_outside(obs, region.outside);  // steps 4, 5
  const std::vector<int> ordered =
      clockwise_from_left(obs.known, obs.robot, obs.heading, region.inside);  // step 2
  if (ordered.empty()) return Decision::go_to(obs.robot);                     // only the robot's own cell
  const double d_s = obs.sensor.range_m / obs.known.resolution_m();
  const std::size_t target = walk_from_head(obs.known, ordered, params_.head_distance_ratio * d_s);  // step 3
  return Decision::go_to(obs.known.cell(ordered[target]));
}

}  // namespace strategies
}  // namespace fsweep
