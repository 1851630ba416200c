#include "engine/world/sensor.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "engine/world/config_error.hpp"

namespace fsweep {
namespace {

/// Relative slack on range comparisons (dimensionless): range_m / resolution_m is rounded in
/// floating point (e.g. 3.0 / 0.3), so a distance that equals the range in exact arithmetic
/// must still count as inside.
constexpr double kRangeSlack = 1e-9;
/// Slack on the field-of-view boundary (radians), for the same reason.
constexpr double kAngleSlack = 1e-9;

/// Squared range in cells² with the slack applied; offsets with dx² + dy² <= this are in range.
double squared_range_limit(double range_cells) {
  return range_cells * range_cells * (1.0 + kRangeSlack) + kRangeSlack;
}

/// Walks the segment from the centre of cell (0, 0) to the centre of cell (dx, dy)
/// (Amanatides & Woo 1987, "A fast voxel traversal algorithm", in exact integer arithmetic).
/// Calls `on_cell(x, y)` for every cell the segment enters before the target and
/// `on_corner(ax, ay, bx, by)` where it passes exactly through a grid corner, with the two cells
/// beside that corner. Either callback returns false to stop the walk; the walk returns false
/// when stopped.
///
/// With centres at integer coordinates, cell boundaries lie at half-integers. The segment meets
/// the (i+1)-th vertical boundary at t = (2i+1) / (2|dx|) and the (j+1)-th horizontal one at
/// t = (2j+1) / (2|dy|); comparing (2i+1)|dy| with (2j+1)|dx| orders them exactly, and equality
/// is a corner. A segment between centres never runs along a boundary.
template <typename OnCell, typename OnCorner>
bool walk_segment(int dx, int dy, OnCell&& on_cell, OnCorner&& on_corner) {
  const int sx = dx > 0 ? 1 : (dx < 0 ? -1 : 0);
  const int sy = dy > 0 ? 1 : (dy < 0 ? -1 : 0);
  const long long ax = std::abs(dx);
  const long long ay = std::abs(dy);
  long long i = 0;  // x steps taken
  long long j = 0;  // y steps taken
  while (i != ax || j != ay) {
    long long cmp = 0;  // < 0: cross a vertical boundary first, > 0: horizontal, 0: corner
    if (ay == 0) {
      cmp = -1;
    } else if (ax == 0) {
      cmp = 1;
    } else {
      cmp = (2 * i + 1) * ay - (2 * j + 1) * ax;
    }
    if (cmp == 0) {
      const int cx = static_cast<int>(i) * sx;
      const int cy = static_cast<int>(j) * sy;
      if (!on_corner(cx + sx, cy, cx, cy + sy)) return false;
      ++i;
      ++j;
    } else if (cmp < 0) {
      ++i;
    } else {
      ++j;
    }
    if (i == ax && j == ay) break;  // entered the target
    if (!on_cell(static_cast<int>(i) * sx, static_cast<int>(j) * sy)) return false;
  }
  return true;
}

/// Smallest absolute difference between two angles (radians), in [0, pi].
double angle_distance(double a, double b) {
  double d = std::fmod(a - b, 2.0 * M_PI);
  if (d < 0.0) d += 2.0 * M_PI;
  return d > M_PI ? 2.0 * M_PI - d : d;
}

/// Reads an optional number at `j[key]` into `out`; ConfigError naming the path otherwise.
void read_number(const nlohmann::json& j, const char* key, const std::string& where, double& out) {
  const auto it = j.find(key);
  if (it == j.end()) return;
  if (!it->is_number()) {
    throw ConfigError(where + "/" + key, "expected a number, got " + it->dump());
  }
  out = it->get<double>();
}

std::string number_text(double v) { return nlohmann::json(v).dump(); }

}  // namespace

SensorParams sensor_params_from_json(const nlohmann::json& j, const std::string& where) {
  require_known_keys(j, {"range_m", "fov_deg", "miss_probability"}, where);
  SensorParams p;
  read_number(j, "range_m", where, p.range_m);
  read_number(j, "fov_deg", where, p.fov_deg);
  read_number(j, "miss_probability", where, p.miss_probability);
  if (!(std::isfinite(p.range_m) && p.range_m > 0.0)) {
    throw ConfigError(where + "/range_m",
                      "range_m = " + number_text(p.range_m) + " is not allowed; must be > 0 (metres)");
  }
  if (!(p.fov_deg > 0.0 && p.fov_deg <= 360.0)) {
    throw ConfigError(where + "/fov_deg", "fov_deg = " + number_text(p.fov_deg) +
                                              " is not allowed; must be in (0, 360] (degrees)");
  }
  if (!(p.miss_probability >= 0.0 && p.miss_probability < 1.0)) {
    throw ConfigError(where + "/miss_probability", "miss_probability = " + number_text(p.miss_probability) +
                                                       " is not allowed; must be in [0, 1)");
  }
  return p;
}

void to_json(nlohmann::json& j, const SensorParams& p) {
  j = nlohmann::json{
      {"range_m", p.range_m}, {"fov_deg", p.fov_deg}, {"miss_probability", p.miss_probability}};
}

Sensor::Sensor(const SensorParams& params, double resolution_m)
    : params_(params), range_cells_(params.range_m / resolution_m) {
  if (!(resolution_m > 0.0) || !std::isfinite(range_cells_) || range_cells_ < 0.0) {
    throw std::invalid_argument(
        "Sensor: needs resolution_m > 0 and a finite range_m >= 0, got resolution_m = " +
        std::to_string(resolution_m) + ", range_m = " + std::to_string(params.range_m));
  }
  // 1. Every offset within range, ordered by squared distance, then row, then column: this is
  //    the "offset-table order" of scan() results and of noise draws.
  const double limit = squared_range_limit(range_cells_);
  const int r = static_cast<int>(std::floor(std::sqrt(limit)));
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      if (static_cast<double>(dx * dx + dy * dy) <= limit) {
        targets_.push_back(
            Target{dx, dy, std::atan2(static_cast<double>(dy), static_cast<double>(dx)), 0, 0});
      }
    }
  }
  std::sort(targets_.begin(), targets_.end(), [](const Target& a, const Target& b) {
    const int da = a.dx * a.dx + a.dy * a.dy;
    const int db = b.dx * b.dx + b.dy * b.dy;
    if (da != db) return da < db;
    if (a.dy != b.dy) return a.dy < b.dy;
    return a.dx < b.dx;
  });
  // 2. The crossings of each target's line of sight, in walk order.
  for (Target& t : targets_) {
    t.first = static_cast<std::uint32_t>(crossings_.size());
    walk_segment(
        t.dx, t.dy,
        [&](int x, int y) {
          crossings_.push_back(Crossing{x, y, 0, 0, false});
          return true;
        },
        [&](int ax, int ay, int bx, int by) {
          crossings_.push_back(Crossing{ax, ay, bx, by, true});
          return true;
        });
    t.count = static_cast<std::uint32_t>(crossings_.size()) - t.first;
  }
  revealed_.reserve(targets_.size());
}

std::span<const int> Sensor::scan(const WorldMap& truth, KnownMap& known, Cell at, double heading_rad,
                                  Rng& rng) {
  revealed_.clear();
  const int width = truth.width();
  const int height = truth.height();
  if (!truth.occupied.in_bounds(at)) return {};
  const std::uint8_t* occ = truth.occupied.data().data();
  const int at_index = at.y * width + at.x;
  const bool limit_fov = params_.fov_deg < 360.0;
  const double half_fov = params_.fov_deg * (M_PI / 360.0) + kAngleSlack;
  const bool noisy = params_.miss_probability > 0.0;

  for (const Target& t : targets_) {
    // 1. The target must lie on the map and still be unknown (known cells never change).
    const int x = at.x + t.dx;
    const int y = at.y + t.dy;
    if (x < 0 || y < 0 || x >= width || y >= height) continue;
    const int index = at_index + t.dy * width + t.dx;
    if (!known.is_unknown(index)) continue;
    const bool own_cell = t.dx == 0 && t.dy == 0;
    // 2. Field of view (the robot's own cell is always seen).
    if (limit_fov && !own_cell && angle_distance(t.angle, heading_rad) > half_fov) continue;
    // 3. Line of sight. Crossed cells lie inside the bounding box of the robot's and the
    //    target's cells, so they are on the map.
    bool clear = true;
    const Crossing* c = crossings_.data() + t.first;
    const Crossing* const end = c + t.count;
    for (; c != end; ++c) {
      const int a = at_index + c->a_dy * width + c->a_dx;
      if (c->corner) {
        const int b = at_index + c->b_dy * width + c->b_dx;
        if (occ[a] != 0 && occ[b] != 0) {
          clear = false;
          break;
        }
      } else if (occ[a] != 0) {
        clear = false;
        break;
      }
    }
    if (!clear) continue;
    // 4. Seeded miss: one draw per visible unknown cell, in table order; the robot's own cell
    //    is never missed.
    if (noisy && !own_cell && uniform01(rng) < params_.miss_probability) continue;
    known.reveal(index, occ[index] != 0);
    revealed_.push_back(index);
  }
  return revealed_;
}

bool Sensor::visible(const WorldMap& truth, Cell at, Cell target) const {
  if (!truth.occupied.in_bounds(at) || !truth.occupied.in_bounds(target)) return false;
  const int dx = target.x - at.x;
  const int dy = target.y - at.y;
  if (static_cast<double>(dx) * dx + static_cast<double>(dy) * dy > squared_range_limit(range_cells_)) {
    return false;
  }
  const auto occupied = [&](int ox, int oy) { return !truth.is_free(Cell{at.x + ox, at.y + oy}); };
  return walk_segment(
      dx, dy, [&](int x, int y) { return !occupied(x, y); },
      [&](int ax, int ay, int bx, int by) { return !(occupied(ax, ay) && occupied(bx, by)); });
}

}  // namespace fsweep
