#include "optimum/cover_route.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <memory>
#include <optional>
#include <queue>
#include <unordered_map>
#include <utility>

#include "core/random.hpp"
#include "core/readable_number.hpp"
#include "search/octile_grid.hpp"
#include "world/sensor.hpp"

namespace fsweep {
inline namespace optimum {
namespace {

constexpr double kImproves = 1e-9;  // metres: a move must shorten the path by more than this

/// Step 1: greedy set cover of the explorable targets the start's scan leaves. With `noise`, each
/// node's gain is scaled by its own factor drawn from [1 - noise, 1 + noise) (a restart's
/// different cover).
std::vector<int> greedy_viewpoints(const CoverageInstance& in, Rng* rng, double noise) {
  std::vector<std::uint8_t> covered(static_cast<std::size_t>(in.targets()), 0);
  for (int t = 0; t < in.targets(); ++t) {
    if (!in.is_explorable(t)) covered[static_cast<std::size_t>(t)] = 1;  // nothing can cover it
  }
  if (in.start_node >= 0) {
    for (const int t : in.sees.row(in.start_node)) covered[static_cast<std::size_t>(t)] = 1;
  }
  // Lazy greedy: gains only fall, so a popped node whose stored gain is still exact is the best.
  std::priority_queue<std::pair<int, int>> heap;  // (gain, -node)
  std::vector<double> scale;
  if (rng != nullptr) {
    scale.resize(static_cast<std::size_t>(in.nodes()));
    for (double& f : scale) f = 1.0 - noise + 2.0 * noise * uniform01(*rng);
  }
  // Gains only fall as targets are covered, with or without the scale: the lazy greedy holds.
  const auto gain = [&](int node) {
    int g = 0;
    for (const int t : in.sees.row(node)) g += covered[static_cast<std::size_t>(t)] == 0 ? 1 : 0;
    if (g == 0 || scale.empty()) return g;
    return std::max(1, static_cast<int>(g * scale[static_cast<std::size_t>(node)]));
  };
  for (int n = 0; n < in.nodes(); ++n) {
    if (in.node_usable[static_cast<std::size_t>(n)] == 0) continue;
    const int g = gain(n);
    if (g > 0) heap.emplace(g, -n);
  }
  std::vector<int> chosen;
  while (!heap.empty()) {
    const auto [stored, negative] = heap.top();
    heap.pop();
    const int node = -negative;
    const int now = gain(node);
    if (now == 0) continue;
    if (now < stored) {
      heap.emplace(now, negative);
      continue;
    }
    chosen.push_back(node);
    for (const int t : in.sees.row(node)) covered[static_cast<std::size_t>(t)] = 1;
  }
  return chosen;
}

/// Distance fields from nodes, computed once per node and shared (one route's steps move few
/// viewpoints, so most fields are asked for again). Emptied when it holds kMaxCachedFields.
class FieldCache {
 public:
  explicit FieldCache(const CoverageInstance& in) : in_(&in) {}
  std::shared_ptr<const std::vector<double>> from(int node) {
    auto it = fields_.find(node);
    if (it != fields_.end()) return it->second;
    if (fields_.size() >= kMaxCachedFields) fields_.clear();
    work_ += static_cast<std::uint64_t>(in_->nodes());
    const int cell = in_->node_cell[static_cast<std::size_t>(node)];
    auto field =
        std::make_shared<const std::vector<double>>(node_distances_m(*in_, std::span<const int>(&cell, 1)));
    fields_.emplace(node, field);
    return field;
  }
  /// Nodes of the fields computed so far (a machine-independent measure of the work done).
  [[nodiscard]] std::uint64_t work() const { return work_; }

 private:
  static constexpr std::size_t kMaxCachedFields = 2048;
  const CoverageInstance* in_;
  std::unordered_map<int, std::shared_ptr<const std::vector<double>>> fields_;
  std::uint64_t work_ = 0;
};

/// Distances between points (nodes), one field per point.
struct PointDistances {
  std::vector<int> points;                                        // nodes
  std::vector<std::shared_ptr<const std::vector<double>>> field;  // per point: metres to every node
  [[nodiscard]] double between(int a, int b) const {
    return (
        *field[static_cast<std::size_t>(a)])[static_cast<std::size_t>(points[static_cast<std::size_t>(b)])];
  }
};

PointDistances distances_of(FieldCache& fields, std::vector<int> points) {
  PointDistances d;
  d.points = std::move(points);
  for (const int node : d.points) d.field.push_back(fields.from(node));
  return d;
}

/// Step 2: nearest neighbour from order[0] = 0 over points 1..n-1.
std::vector<int> nearest_neighbour_order(const PointDistances& d) {
  const int n = static_cast<int>(d.points.size());
  std::vector<int> order{0};
  std::vector<std::uint8_t> used(static_cast<std::size_t>(n), 0);
  used[0] = 1;
  for (int step = 1; step < n; ++step) {
    int best = -1;
    for (int p = 1; p < n; ++p) {
      if (used[static_cast<std::size_t>(p)] == 0 &&
          (best < 0 || d.between(order.back(), p) < d.between(order.back(), best))) {
        best = p;
      }
    }
    used[static_cast<std::size_t>(best)] = 1;
    order.push_back(best);
  }
  return order;
}

/// One 2-opt pass on the open path; true when it improved.
bool two_opt_pass(const PointDistances& d, std::vector<int>& o) {
  bool improved = false;
  const std::size_t n = o.size();
  for (std::size_t i = 1; i + 1 < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const double before = d.between(o[i - 1], o[i]) + (j + 1 < n ? d.between(o[j], o[j + 1]) : 0.0);
      const double after = d.between(o[i - 1], o[j]) + (j + 1 < n ? d.between(o[i], o[j + 1]) : 0.0);
      if (after < before - kImproves) {
        std::reverse(o.begin() + static_cast<std::ptrdiff_t>(i),
                     o.begin() + static_cast<std::ptrdiff_t>(j) + 1);
        improved = true;
      }
    }
  }
  return improved;
}

/// One Or-opt pass (segments of 1-3 points moved elsewhere, either way round); true when it
/// improved.
bool or_opt_pass(const PointDistances& d, std::vector<int>& o) {
  bool improved = false;
  for (std::size_t len = 1; len <= 3; ++len) {
    for (std::size_t i = 1; i + len <= o.size(); ++i) {
      const std::size_t j = i + len - 1;  // segment o[i..j]
      const bool at_end = j + 1 == o.size();
      const double removed = d.between(o[i - 1], o[i]) + (at_end ? 0.0 : d.between(o[j], o[j + 1])) -
                             (at_end ? 0.0 : d.between(o[i - 1], o[j + 1]));
      std::vector<int> seg(o.begin() + static_cast<std::ptrdiff_t>(i),
                           o.begin() + static_cast<std::ptrdiff_t>(j) + 1);
      std::vector<int> rest(o.begin(), o.begin() + static_cast<std::ptrdiff_t>(i));
      rest.insert(rest.end(), o.begin() + static_cast<std::ptrdiff_t>(j) + 1, o.end());
      double best_gain = kImproves;
      std::size_t best_at = 0;
      bool best_reversed = false;
      for (std::size_t k = 0; k < rest.size(); ++k) {  // insert after rest[k]
        const bool end = k + 1 == rest.size();
        for (const bool reversed : {false, true}) {
          const int first = reversed ? seg.back() : seg.front();
          const int last = reversed ? seg.front() : seg.back();
          const double added = d.between(rest[k], first) + (end ? 0.0 : d.between(last, rest[k + 1])) -
                               (end ? 0.0 : d.between(rest[k], rest[k + 1]));
          if (removed - added > best_gain) {
            best_gain = removed - added;
            best_at = k;
            best_reversed = reversed;
          }
        }
      }
      if (best_gain > kImproves) {
        if (best_reversed) std::reverse(seg.begin(), seg.end());
        rest.insert(rest.begin() + static_cast<std::ptrdiff_t>(best_at) + 1, seg.begin(), seg.end());
        o = std::move(rest);
        improved = true;
      }
    }
  }
  return improved;
}

void improve(const PointDistances& d, std::vector<int>& order, int max_passes) {
  for (int pass = 0; pass < max_passes; ++pass) {
    const bool a = two_opt_pass(d, order);
    const bool b = or_opt_pass(d, order);
    if (!a && !b) break;
  }
}

/// Cells from node a to node b, without a's cell.
std::vector<int> leg(const CoverageInstance& in, int a, int b) {
  std::vector<int> path = shortest_path_cells(in, in.node_cell[static_cast<std::size_t>(a)],
                                              in.node_cell[static_cast<std::size_t>(b)]);
  if (!path.empty()) path.erase(path.begin());
  return path;
}

/// True when the cells of `order`'s route see every explorable target (by the scans' tables).
bool covers_all(const CoverageInstance& in, const PointDistances& d, const std::vector<int>& order) {
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(in.targets()), 0);
  const auto mark = [&](int cell) {
    for (const int t : in.sees.row(in.node_of_cell[static_cast<std::size_t>(cell)]))
      seen[static_cast<std::size_t>(t)] = 1;
  };
  mark(in.node_cell[static_cast<std::size_t>(d.points[static_cast<std::size_t>(order[0])])]);
  for (std::size_t k = 1; k < order.size(); ++k) {
    for (const int c : leg(in, d.points[static_cast<std::size_t>(order[k - 1])],
                           d.points[static_cast<std::size_t>(order[k])]))
      mark(c);
  }
  for (int t = 0; t < in.targets(); ++t) {
    if (seen[static_cast<std::size_t>(t)] == 0 && in.is_explorable(t)) return false;
  }
  return true;
}

/// Step 3: drops viewpoints the rest of the route sees on its way. Returns true when it dropped
/// one. `order` indexes d.points.
bool prune(const CoverageInstance& in, const PointDistances& d, std::vector<int>& order) {
  const std::size_t n = order.size();
  if (n < 2) return false;
  std::vector<std::vector<int>> legs(n);  // legs[k]: cells of the leg into order[k] (k >= 1)
  std::vector<int> count(static_cast<std::size_t>(in.targets()), 0);
  const auto add = [&](const std::vector<int>& cells, int sign) {
    for (const int c : cells) {
      for (const int t : in.sees.row(in.node_of_cell[static_cast<std::size_t>(c)]))
        count[static_cast<std::size_t>(t)] += sign;
    }
  };
  add({in.node_cell[static_cast<std::size_t>(d.points[static_cast<std::size_t>(order[0])])]}, 1);
  for (std::size_t k = 1; k < n; ++k) {
    legs[k] = leg(in, d.points[static_cast<std::size_t>(order[k - 1])],
                  d.points[static_cast<std::size_t>(order[k])]);
    add(legs[k], 1);
  }
  std::vector<std::uint8_t> dropped(n, 0);
  bool any = false;
  std::size_t prev = 0;  // the last kept position before k
  for (std::size_t k = 1; k < n; ++k) {
    std::size_t next = k + 1;
    // Try dropping order[k]: the legs into k and into next become one leg prev -> next.
    std::vector<int> joined;
    if (next < n)
      joined = leg(in, d.points[static_cast<std::size_t>(order[prev])],
                   d.points[static_cast<std::size_t>(order[next])]);
    add(legs[k], -1);
    if (next < n) add(legs[next], -1);
    add(joined, 1);
    bool keeps = true;
    for (int t = 0; t < in.targets() && keeps; ++t)
      keeps = count[static_cast<std::size_t>(t)] > 0 || !in.is_explorable(t);
    if (keeps) {
      dropped[k] = 1;
      any = true;
      if (next < n) legs[next] = std::move(joined);
      legs[k].clear();
    } else {
      add(joined, -1);
      add(legs[k], 1);
      if (next < n) add(legs[next], 1);
      prev = k;
    }
  }
  if (!any) return false;
  std::vector<int> kept;
  for (std::size_t k = 0; k < n; ++k) {
    if (dropped[k] == 0) kept.push_back(order[k]);
  }
  order = std::move(kept);
  return true;
}

/// The route's points as nodes, in order.
std::vector<int> nodes_of(const PointDistances& d, const std::vector<int>& order) {
  std::vector<int> nodes;
  nodes.reserve(order.size());
  for (const int p : order) nodes.push_back(d.points[static_cast<std::size_t>(p)]);
  return nodes;
}

/// Step 3b: moves each viewpoint (nodes[1..]) to the usable node that sees every target only its
/// two legs see and is closest to its neighbours on the route (the sum of the two leg lengths),
/// when that shortens the route. The new legs pass through the new node, whose scan reveals what
/// the old legs alone revealed, so the route keeps its coverage. Returns true when it moved one.
bool relocate(const CoverageInstance& in, FieldCache& fields, std::vector<int>& nodes) {
  const std::size_t n = nodes.size();
  if (n < 2) return false;
  std::vector<std::vector<int>> legs(n);  // legs[k]: the cells of the leg into nodes[k] (k >= 1)
  std::vector<int> count(static_cast<std::size_t>(in.targets()), 0);
  const auto add = [&](const std::vector<int>& cells, int sign) {
    for (const int c : cells) {
      for (const int t : in.sees.row(in.node_of_cell[static_cast<std::size_t>(c)]))
        count[static_cast<std::size_t>(t)] += sign;
    }
  };
  add({in.node_cell[static_cast<std::size_t>(nodes[0])]}, 1);
  for (std::size_t k = 1; k < n; ++k) {
    legs[k] = leg(in, nodes[k - 1], nodes[k]);
    add(legs[k], 1);
  }
  std::shared_ptr<const std::vector<double>> from_prev = fields.from(nodes[0]);
  std::vector<int> hits(static_cast<std::size_t>(in.nodes()), 0);
  bool moved = false;
  for (std::size_t k = 1; k < n; ++k) {
    const bool last = k + 1 == n;
    const std::shared_ptr<const std::vector<double>> from_next = last ? nullptr : fields.from(nodes[k + 1]);
    const auto cost = [&](int node) {
      return (*from_prev)[static_cast<std::size_t>(node)] +
             (last ? 0.0 : (*from_next)[static_cast<std::size_t>(node)]);
    };
    // The targets only legs k and k + 1 see.
    add(legs[k], -1);
    if (!last) add(legs[k + 1], -1);
    std::vector<int> only;
    for (const std::vector<int>* cells : {&legs[k], last ? nullptr : &legs[k + 1]}) {
      if (cells == nullptr) continue;
      for (const int c : *cells) {
        for (const int t : in.sees.row(in.node_of_cell[static_cast<std::size_t>(c)])) {
          if (count[static_cast<std::size_t>(t)] == 0 && in.is_explorable(t)) {
            count[static_cast<std::size_t>(t)] = -1;  // listed once
            only.push_back(t);
          }
        }
      }
    }
    for (const int t : only) count[static_cast<std::size_t>(t)] = 0;
    // The usable nodes that see all of them (every node when none).
    int best = nodes[k];
    double best_cost = cost(nodes[k]);
    for (const int t : only) {
      for (const int v : in.seen_from.row(t)) ++hits[static_cast<std::size_t>(v)];
    }
    const int need = static_cast<int>(only.size());
    for (int v = 0; v < in.nodes(); ++v) {
      if (hits[static_cast<std::size_t>(v)] != need || in.node_usable[static_cast<std::size_t>(v)] == 0)
        continue;
      const double c = cost(v);
      if (c < best_cost - kImproves) {
        best = v;
        best_cost = c;
      }
    }
    for (const int t : only) {
      for (const int v : in.seen_from.row(t)) hits[static_cast<std::size_t>(v)] = 0;
    }
    if (best != nodes[k]) {
      nodes[k] = best;
      legs[k] = leg(in, nodes[k - 1], best);
      if (!last) legs[k + 1] = leg(in, best, nodes[k + 1]);
      moved = true;
    }
    add(legs[k], 1);
    if (!last) add(legs[k + 1], 1);
    from_prev = fields.from(nodes[k]);
  }
  return moved;
}

/// Step 4: the optimal split of `order` (points after order[0]) into trips within `range_m`, each
/// viewpoint costing `per_viewpoint_m` more (look_around()'s steps). Returns the positions in
/// `order` where trips 2, 3, ... start; nullopt when some viewpoint cannot be reached and left
/// within one charge.
std::optional<std::vector<std::size_t>> split_trips(const PointDistances& d, const std::vector<int>& order,
                                                    int dock_point, double range_m, double per_viewpoint_m) {
  const std::size_t m = order.size();      // positions 1..m-1 are viewpoints
  std::vector<double> best(m, kInfinity);  // best[j]: visiting positions 1..j, back at the dock
  std::vector<std::size_t> cut(m, 0);
  best[0] = 0.0;
  double final_best = m == 1 ? 0.0 : kInfinity;
  std::size_t final_cut = 0;
  for (std::size_t i = 1; i < m; ++i) {  // a trip starting at position i
    if (best[i - 1] == kInfinity) continue;
    const int from = i == 1 ? order[0] : dock_point;
    double travel = d.between(from, order[i]);
    for (std::size_t j = i; j < m; ++j) {
      if (j > i) travel += d.between(order[j - 1], order[j]);
      travel += per_viewpoint_m;
      const double back = d.between(order[j], dock_point);
      if (travel + back > range_m) break;
      if (best[i - 1] + travel + back < best[j]) {
        best[j] = best[i - 1] + travel + back;
        cut[j] = i;
      }
      if (j + 1 == m && best[i - 1] + travel < final_best) {
        final_best = best[i - 1] + travel;
        final_cut = i;
      }
    }
  }
  if (final_best == kInfinity) return std::nullopt;
  std::vector<std::size_t> starts;
  for (std::size_t i = final_cut; i > 1; i = cut[i - 1]) starts.push_back(i);
  std::reverse(starts.begin(), starts.end());
  return starts;
}

/// The 45-degree headings between the headings look_around() faces, and how many it faces.
int look_step(const CoverageInstance& in) { return std::clamp(static_cast<int>(in.fov_deg / 45.0), 1, 4); }
int look_turns(const CoverageInstance& in) {
  return in.fov_deg >= 360.0 ? 1 : (8 + look_step(in) - 1) / look_step(in);
}

/// The most look_around() adds to a route at one point (metres): a diagonal step out and back
/// per heading turned to.
double look_around_m(const CoverageInstance& in) {
  return (look_turns(in) - 1) * 2.0 * kSqrt2 * in.resolution_m;
}

/// With a field of view below 360 degrees, the robot on the route's last cell turns to face, in
/// turn, headings whose fields of view together with its arrival heading's go round the circle
/// (45-degree headings, fov rounded down to them): each by a step to the neighbour behind that
/// heading and back. `heading` is the heading on arrival, updated. Headings whose neighbour cannot
/// be stepped to are left out (the replay then says whether the route still covers).
void look_around(const CoverageInstance& in, std::vector<int>& cells, int& heading) {
  if (in.fov_deg >= 360.0) return;
  const int step = look_step(in);
  const int turns = look_turns(in);
  const Cell at = in.truth.cell(cells.back());
  const int first = heading;
  for (int i = 1; i < turns; ++i) {
    const int h = (first + i * step) % 8;
    const Cell behind{at.x - kDirections[static_cast<std::size_t>(h)].x,
                      at.y - kDirections[static_cast<std::size_t>(h)].y};
    if (in.node_at(behind) < 0 || !octile_step_allowed(in.truth, at, behind, in.allow_corner_cutting))
      continue;
    cells.push_back(in.truth.index(behind));
    cells.push_back(in.truth.index(at));
    heading = h;
  }
}

/// Appends `path` (cells after the route's last) and follows the heading.
void walk(const CoverageInstance& in, std::vector<int>& cells, const std::vector<int>& path, int& heading) {
  for (const int c : path) {
    const Cell a = in.truth.cell(cells.back());
    const Cell b = in.truth.cell(c);
    heading = heading_of(b.x - a.x, b.y - a.y);
    cells.push_back(c);
  }
}

/// The route's cells: legs between consecutive points, back to the dock before each trip start,
/// looking around at the start and each viewpoint with a field of view below 360 degrees.
CoverRoute assemble(const CoverageInstance& in, const PointDistances& d, const std::vector<int>& order,
                    const std::vector<std::size_t>& trip_starts) {
  CoverRoute r;
  r.cells.push_back(in.node_cell[static_cast<std::size_t>(d.points[static_cast<std::size_t>(order[0])])]);
  r.trip_starts.push_back(0);
  int heading = in.start_heading;
  look_around(in, r.cells, heading);
  std::size_t next_trip = 0;
  int at = d.points[static_cast<std::size_t>(order[0])];
  for (std::size_t k = 1; k < order.size(); ++k) {
    if (next_trip < trip_starts.size() && trip_starts[next_trip] == k) {
      walk(in, r.cells, leg(in, at, in.dock_node), heading);
      at = in.dock_node;
      r.trip_starts.push_back(r.cells.size() - 1);
      ++next_trip;
    }
    const int to = d.points[static_cast<std::size_t>(order[k])];
    walk(in, r.cells, leg(in, at, to), heading);
    look_around(in, r.cells, heading);
    r.viewpoints.push_back(to);
    at = to;
  }
  return r;
}

}  // namespace

RouteReplay replay_route(const CoverageInstance& in, const RunSpec& spec, std::span<const int> cells) {
  RouteReplay r;
  r.explorable = in.explorable_count();
  if (cells.empty() || cells.front() != in.truth.index(in.start)) return r;
  SensorParams noiseless = spec.robot.sensor;
  noiseless.miss_probability = 0.0;
  Sensor sensor(noiseless, in.resolution_m);
  r.known = KnownMap(in.width, in.height, in.resolution_m);
  Rng unused(0);
  const EnergyModel& energy = spec.robot.energy;
  const double capacity = spec.robot.battery_capacity;
  int heading = in.start_heading;
  double used = 0.0;  // energy since the last charge
  const auto sense = [&](Cell at) {
    int fresh = 0;
    for (const int c : sensor.scan(*spec.map, r.known, at, heading_angle(heading), unused)) {
      const int t = in.target_of_cell[static_cast<std::size_t>(c)];
      if (t >= 0 && in.is_explorable(t)) ++fresh;  // out of reach: not counted
    }
    if (fresh > 0) {
      r.revealed += fresh;
      r.distance_to_final_coverage_m = r.length_m;
    }
  };
  sense(in.start);
  for (std::size_t i = 1; i < cells.size(); ++i) {
    const Cell a = in.truth.cell(cells[i - 1]);
    const Cell b = in.truth.cell(cells[i]);
    if (!octile_step_allowed(in.truth, a, b, in.allow_corner_cutting)) return r;
    const int h = heading_of(b.x - a.x, b.y - a.y);
    const double step_cells = step_length(h);
    used += energy.turn(heading_difference(h, heading)) + energy.travel(step_cells, in.resolution_m);
    heading = h;
    r.length_m += step_cells * in.resolution_m;
    if (used > capacity) r.battery_ok = false;
    if (in.limited_battery() && b == in.dock && i + 1 < cells.size()) {
      used = 0.0;
      r.recharge_steps.push_back(static_cast<int>(i));
      if (r.revealed < r.explorable) ++r.trips;
    }
    if (r.revealed < r.explorable) sense(b);
  }
  r.valid = true;
  return r;
}

namespace {

/// Points (the start first, the dock last when it is no viewpoint) and an order over them.
struct Plan {
  PointDistances d;
  std::vector<int> order;
  int dock_point = -1;  // the dock's index in d.points, -1 without a battery
};

Plan plan_of(const CoverageInstance& in, FieldCache& fields, std::vector<int> points) {
  Plan plan;
  for (std::size_t p = 0; p < points.size(); ++p) plan.order.push_back(static_cast<int>(p));
  if (in.limited_battery()) {
    const auto it = std::find(points.begin(), points.end(), in.dock_node);
    plan.dock_point = static_cast<int>(it - points.begin());
    if (it == points.end()) points.push_back(in.dock_node);  // no viewpoint: not in the order
  }
  plan.d = distances_of(fields, std::move(points));
  return plan;
}

double path_length(const Plan& plan) {
  double length = 0.0;
  for (std::size_t k = 1; k < plan.order.size(); ++k)
    length += plan.d.between(plan.order[k - 1], plan.order[k]);
  return length;
}

/// Steps 2 and 3 on `plan`'s order: improvement, then pruning rounds. Pruning and relocation keep
/// the coverage of the order they change; improving the order changes the paths between viewpoints
/// and may lose some, so an improved order is kept only if it still covers.
void improve_and_prune(const CoverageInstance& in, Plan& plan, int max_passes) {
  std::vector<int> improved = plan.order;
  improve(plan.d, improved, max_passes);
  if (covers_all(in, plan.d, improved)) plan.order = std::move(improved);
  for (int round = 0; round < 8; ++round) {
    std::vector<int> pruned = plan.order;
    if (!prune(in, plan.d, pruned)) break;
    std::vector<int> improved = pruned;
    improve(plan.d, improved, max_passes);
    plan.order = covers_all(in, plan.d, improved) ? std::move(improved) : std::move(pruned);
  }
}

/// Viewpoints for the explorable targets `replay` left unrevealed (the legs home to the dock
/// replace legs between viewpoints that pruning or relocation counted on): for each such target,
/// in id order and unless a viewpoint added before sees it, the usable node that sees it with the
/// cheapest insertion into `plan`'s order (as one trip: an insertion cost that counts the legs to
/// and from the dock made the route longer on the maps tried). Returns the new order's nodes; empty when none
/// is missing or a target has no usable viewpoint.
std::vector<int> with_missing_viewpoints(const CoverageInstance& in, const Plan& plan,
                                         const RouteReplay& replay) {
  std::vector<std::pair<std::size_t, int>> inserts;  // (before position k of the order, node)
  std::vector<std::uint8_t> handled(static_cast<std::size_t>(in.targets()), 0);
  const std::size_t m = plan.order.size();
  for (int t = 0; t < in.targets(); ++t) {
    if (!in.is_explorable(t) || handled[static_cast<std::size_t>(t)] != 0 ||
        !replay.known.is_unknown(in.target_cell[static_cast<std::size_t>(t)]))
      continue;
    // Insertion costs from the distance fields of the plan's points (the lengths are symmetric).
    double best_cost = kInfinity;
    std::pair<std::size_t, int> best{0, -1};
    for (const int v : in.seen_from.row(t)) {
      if (in.node_usable[static_cast<std::size_t>(v)] == 0) continue;
      const auto to = [&](int point) {
        return (*plan.d.field[static_cast<std::size_t>(point)])[static_cast<std::size_t>(v)];
      };
      const auto detour = [&](int a, int b) { return to(a) + to(b) - plan.d.between(a, b); };
      for (std::size_t k = 1; k <= m; ++k) {
        const double cost = k == m ? to(plan.order[k - 1]) : detour(plan.order[k - 1], plan.order[k]);
        if (cost < best_cost) {
          best_cost = cost;
          best = {k, v};
        }
      }
    }
    if (best.second < 0) return {};
    inserts.push_back(best);
    for (const int seen : in.sees.row(best.second)) handled[static_cast<std::size_t>(seen)] = 1;
  }
  if (inserts.empty()) return {};
  std::stable_sort(inserts.begin(), inserts.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<int> nodes;
  std::size_t next = 0;
  for (std::size_t k = 0; k <= m; ++k) {
    for (; next < inserts.size() && inserts[next].first == k; ++next) nodes.push_back(inserts[next].second);
    if (k < m) nodes.push_back(plan.d.points[static_cast<std::size_t>(plan.order[k])]);
  }
  return nodes;
}

/// Rounds of with_missing_viewpoints() per candidate order.
constexpr int kRepairRounds = 4;

/// Steps 1-4 from one cover: the restart `restart` (0: the plain greedy cover).
CoverRoute one_route(const CoverageInstance& in, const RunSpec& spec, const RouteOptions& options,
                     int restart, FieldCache& fields) {
  std::vector<int> points{in.start_node};
  Rng rng = make_rng(static_cast<std::uint64_t>(restart), "optimum/route-restart");
  const std::vector<int> viewpoints =
      greedy_viewpoints(in, restart == 0 ? nullptr : &rng, options.restart_noise);
  points.insert(points.end(), viewpoints.begin(), viewpoints.end());
  Plan plan = plan_of(in, fields, points);
  plan.order = nearest_neighbour_order(plan.d);
  if (plan.dock_point >= static_cast<int>(points.size())) {  // the dock is no viewpoint
    plan.order.erase(std::find(plan.order.begin(), plan.order.end(), plan.dock_point));
  }
  improve(plan.d, plan.order, options.max_passes);
  const Plan unpruned = plan;
  improve_and_prune(in, plan, options.max_passes);
  // Step 3b: viewpoints moved towards their neighbours, then the order improved and pruned
  // again, while that shortens the path.
  std::vector<Plan> tried;
  for (int round = 0; round < options.max_relocations; ++round) {
    std::vector<int> nodes = nodes_of(plan.d, plan.order);
    if (!relocate(in, fields, nodes)) break;
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    Plan next = plan_of(in, fields, nodes);
    improve_and_prune(in, next, options.max_passes);
    if (path_length(next) >= path_length(plan) - kImproves) break;
    tried.push_back(std::move(plan));
    plan = std::move(next);
  }
  // With the 360-degree sensor and no battery the order covers by construction (covers_all()).
  if (!in.limited_battery() && in.fov_deg >= 360.0) return assemble(in, plan.d, plan.order, {});
  // Trips: the split on lengths, then the replay with turns; a split the turns break is redone
  // with a smaller range per charge. A trip's way home replaces the path between two viewpoints
  // that pruning or relocation may have counted on (and a narrow field of view does not see what
  // the 360-degree tables say the legs see), so targets the replay misses get viewpoints back
  // (with_missing_viewpoints(), a few rounds), and then the earlier plans, down to the unpruned
  // order, are tried.
  std::vector<const Plan*> candidates{&plan};
  for (auto it = tried.rbegin(); it != tried.rend(); ++it) candidates.push_back(&*it);
  candidates.push_back(&unpruned);
  for (const Plan* candidate : candidates) {
    Plan repaired = *candidate;
    for (int round = 0; round <= kRepairRounds; ++round) {
      double range = in.range_per_charge_m;
      std::optional<RouteReplay> missed;
      for (int attempt = 0; attempt < 12; ++attempt) {
        const auto starts = in.limited_battery() ? split_trips(repaired.d, repaired.order,
                                                               repaired.dock_point, range, look_around_m(in))
                                                 : std::optional<std::vector<std::size_t>>(std::in_place);
        if (!starts) break;
        CoverRoute route = assemble(in, repaired.d, repaired.order, *starts);
        RouteReplay replay = replay_route(in, spec, route.cells);
        if (replay.covers()) return route;
        if (replay.battery_ok) {  // covers less
          missed = std::move(replay);
          break;
        }
        range *= 0.97;
      }
      if (!missed || round == kRepairRounds) break;
      std::vector<int> nodes = with_missing_viewpoints(in, repaired, *missed);
      if (nodes.empty()) break;
      repaired = plan_of(in, fields, std::move(nodes));
    }
  }
  return assemble(in, plan.d, plan.order, {});  // none covers: the replay says why
}

}  // namespace

CoverRoute cover_route(const CoverageInstance& in, const RunSpec& spec, const RouteOptions& options) {
  CoverRoute best;
  const std::uint64_t viewpoints =
      greedy_viewpoints(in, nullptr, 0.0).size() + 2;  // with the start, the dock
  const std::uint64_t cells = viewpoints * static_cast<std::uint64_t>(in.nodes());
  if (cells > options.max_field_cells) {
    const auto mb = [](std::uint64_t entries) {
      return readable_number(static_cast<double>(entries) * 8e-6, 4);
    };
    best.refused = "the covering route's distance fields (" +
                   readable_number(static_cast<double>(viewpoints)) + " viewpoints x " +
                   readable_number(in.nodes()) + " cells, " + mb(cells) + " MB) are above the limit of " +
                   mb(options.max_field_cells) + " MB";
    return best;
  }
  double best_m = kInfinity;
  bool best_covers = false;
  FieldCache fields(in);  // shared by the restarts: their covers share many viewpoints
  for (int restart = 0; restart < std::max(1, options.restarts); ++restart) {
    CoverRoute route = one_route(in, spec, options, restart, fields);
    const RouteReplay replay = replay_route(in, spec, route.cells);
    const bool better = replay.covers() ? (!best_covers || replay.distance_to_final_coverage_m < best_m)
                                        : (restart == 0);  // a route that misses: only as the last resort
    if (better) {
      best_covers = replay.covers();
      best_m = replay.distance_to_final_coverage_m;
      best = std::move(route);
    }
    if (fields.work() > options.restart_work) break;
  }
  return best;
}

}  // namespace optimum
}  // namespace fsweep
