#include "sim/reveal_bound.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>

#include "search/distance_field.hpp"
#include "sim/run_setup.hpp"
#include "world/known_map.hpp"
#include "world/sensor.hpp"

namespace fsweep {
inline namespace sim {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// Cells of reveal distance per bin: the bound tries rho in these steps. On the Manhattan class one
/// cell per bin gave the same bound at the start within 0.02% and took 4.4% of a search's time.
constexpr double kCellsPerBin = 4.0;

/// The legs of the rest of a run that reach rho from the dock (reveal_bound.hpp): the travel
/// they leave out and the far area they can hold at most, each.
struct Leg {
  double overhead_m = 0.0;
  double area_m2 = 0.0;
  int reaching = 0;
};

/// The bound for one rho, with `far_m2` the area of the needed cells beyond it (> 0); +infinity
/// when no way of travelling reveals it.
double travel_beyond(const RevealState& s, double rho, double far_m2) {
  const double two_r = 2.0 * s.reach_m;
  const double disc = std::numbers::pi * s.reach_m * s.reach_m;
  // A leg of length at most `length` that leaves out `overhead` of it; none when it cannot.
  const auto leg = [&](double length, double overhead) {
    return length >= overhead ? Leg{overhead, two_r * (length - overhead) + disc, 1} : Leg{kInfinity, 0.0, 0};
  };
  const double to_rho = std::max(0.0, rho - s.dock_m);
  // The run ends before its next recharge.
  double best = kInfinity;
  if (const Leg only = leg(s.first_charge_m, to_rho); only.area_m2 >= far_m2) {
    best = to_rho + std::max(0.0, (far_m2 - disc) / two_r);
  }
  if (!std::isfinite(s.dock_m) || !(s.first_charge_m >= s.dock_m)) return best;  // no recharge ahead
  // It recharges first: the first leg, full legs from the dock to the dock, the last leg; the
  // first and the last may or may not reach rho.
  const Leg full = leg(s.charge_m, 2.0 * rho);
  for (const Leg first : {leg(s.first_charge_m, to_rho + rho), Leg{s.dock_m, 0.0, 0}}) {
    if (!std::isfinite(first.overhead_m)) continue;
    for (const Leg last : {leg(s.charge_m, rho), Leg{0.0, 0.0, 0}}) {
      if (!std::isfinite(last.overhead_m)) continue;
      const double rest = far_m2 - first.area_m2 - last.area_m2;
      double legs = 0.0;
      if (rest > 0.0) {
        if (!(full.area_m2 > 0.0)) continue;
        legs = std::max(1.0, std::ceil(rest / full.area_m2));
      }
      const double reaching = first.reaching + last.reaching + legs;
      const double between = legs > 0.0 ? legs * full.overhead_m : 0.0;
      best = std::min(best, first.overhead_m + last.overhead_m + between +
                                std::max(0.0, (far_m2 - reaching * disc) / two_r));
    }
  }
  return best;
}

}  // namespace

RevealGeometry reveal_geometry(const RunSetup& setup, Cell dock) {
  const WorldMap& truth = setup.map();
  RevealGeometry out;
  out.bin_m = kCellsPerBin * setup.resolution_m;
  DistanceField field;
  DistanceQuery query;
  query.allow_corner_cutting = setup.allow_corner_cutting();
  field.compute(fully_known(truth), dock, query);
  const int cells = setup.reachable.size();
  out.dock_m.assign(static_cast<std::size_t>(cells), kInfinity);
  for (int i = 0; i < cells; ++i) out.dock_m[static_cast<std::size_t>(i)] = field.distance_m(i);
  // h: the least g of a reachable cell whose sensor disc (disc_extent(): the sensor's own range
  // rule) holds the cell. R: the farthest offset in range, plus half a cell's diagonal.
  const std::vector<int> extent = disc_extent(setup.spec.robot.sensor.range_m / setup.resolution_m);
  const int radius = static_cast<int>(extent.size()) - 1;
  double farthest = 0.0;
  for (int u = 0; u <= radius; ++u) {
    const int v = extent[static_cast<std::size_t>(u)];
    if (v >= 0) farthest = std::max(farthest, std::hypot(u, v));
  }
  out.reach_m = (farthest + std::sqrt(0.5)) * setup.resolution_m;
  const int width = truth.width();
  const int height = truth.height();
  std::vector<double> reveal(static_cast<std::size_t>(cells), kInfinity);
  for (int i = 0; i < cells; ++i) {
    const double g = out.dock_m[static_cast<std::size_t>(i)];
    if (setup.reachable[i] == 0 || !std::isfinite(g)) continue;
    const Cell s = setup.reachable.cell(i);
    for (int dy = std::max(-radius, -s.y); dy <= std::min(radius, height - 1 - s.y); ++dy) {
      const int w = extent[static_cast<std::size_t>(std::abs(dy))];
      const int first = (s.y + dy) * width + std::max(0, s.x - w);
      const int last = (s.y + dy) * width + std::min(width - 1, s.x + w);
      for (int at = first; at <= last; ++at) {
        double& h = reveal[static_cast<std::size_t>(at)];
        h = std::min(h, g);
      }
    }
  }
  out.bin.assign(static_cast<std::size_t>(cells), -1);
  for (int i = 0; i < cells; ++i) {
    const double h = reveal[static_cast<std::size_t>(i)];
    if (setup.reachable[i] == 0 || !std::isfinite(h)) continue;
    const auto b = static_cast<std::int32_t>(std::floor(h / out.bin_m));
    out.bin[static_cast<std::size_t>(i)] = b;
    out.bins = std::max(out.bins, b + 1);
  }
  return out;
}

Charges charges_m(const Battery& battery, const EnergyModel& energy, double resolution_m) {
  // Battery::draw lets a draw overrun the charge by 1e-9 of the capacity, and leaves an empty
  // battery at 0: one step per charge can overrun, unless a step costs no more than that slack
  // (then every step can, and the charge bounds nothing). Every metre costs at least the
  // straight-travel energy (turns cost >= 0).
  const double per_cell = energy.travel_per_cell(resolution_m);
  const double slack = 1e-9 * battery.capacity();
  if (battery.unlimited() || !(per_cell > slack)) return Charges{kInfinity, kInfinity};
  const double per_metre = per_cell / resolution_m;
  return Charges{(battery.level() + slack) / per_metre * (1.0 + 1e-9),
                 (battery.capacity() + slack) / per_metre * (1.0 + 1e-9)};
}

double travel_to_reveal_m(const RevealState& s, std::span<const int> unknown_by_bin) {
  if (!(s.needed_cells > 0.0)) return 0.0;
  const double disc = std::numbers::pi * s.reach_m * s.reach_m;
  const double needed_m2 = s.needed_cells * s.cell_area_m2;
  double bound = std::max(0.0, (needed_m2 - disc) / (2.0 * s.reach_m));  // the tube alone
  // From rho = pi R / 4 on another leg never shortens the travel (reveal_bound.hpp).
  const double least_rho = std::numbers::pi * s.reach_m / 4.0;
  double nearer = 0.0;  // unknown cells with h < rho
  for (std::size_t j = 0; j <= unknown_by_bin.size(); ++j) {
    if (j > 0) nearer += unknown_by_bin[j - 1];
    const double far_m2 = (s.needed_cells - nearer) * s.cell_area_m2;
    if (!(far_m2 > 0.0)) break;
    const double rho = static_cast<double>(j) * s.bin_m;
    if (rho < least_rho) continue;
    const double beyond = travel_beyond(s, rho, far_m2);
    if (std::isfinite(beyond)) bound = std::max(bound, beyond);
  }
  return bound;
}

}  // namespace sim
}  // namespace fsweep
