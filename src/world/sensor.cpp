#include "world/sensor.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "core/config_error.hpp"

namespace fsweep {
inline namespace world {
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

/// Walks a ray from the centre of the robot's cell to the end point (ex, ey), given in doubled
/// coordinates relative to that centre: cell (x, y) relative to the robot's cell spans
/// (2x - 1, 2x + 1) x (2y - 1, 2y + 1), so the target's centre is (2dx, 2dy) and the midpoints
/// of its faces are (2dx - sign(dx), 2dy) and (2dx, 2dy - sign(dy)). Calls `on_cell(x, y)` for
/// every cell the ray enters strictly before its end point (for a centre ray the last one is
/// the target itself) and `on_corner(ax, ay, bx, by)` where it passes exactly through a grid
/// corner, with the two cells beside that corner. Either callback returns false to stop the
/// walk; the walk returns false when stopped.
///
/// Amanatides & Woo 1987 ("A fast voxel traversal algorithm") in exact integer arithmetic:
/// cell boundaries lie at odd coordinates; the ray meets its (i+1)-th vertical boundary at
/// t = (2i+1) / |ex| and its (j+1)-th horizontal one at t = (2j+1) / |ey|, t in [0, 1];
/// comparing (2i+1)|ey| with (2j+1)|ex| orders them exactly, and equality is a corner. Only
/// boundaries with t < 1 are crossed: one at t = 1 holds the end point (the face a face ray
/// ends on). A ray from a cell centre never runs along a boundary, and a face midpoint is
/// never a corner, so no corner lies at t = 1.
template <typename OnCell, typename OnCorner>
bool walk_ray(int ex, int ey, OnCell&& on_cell, OnCorner&& on_corner) {
  const int sx = ex > 0 ? 1 : (ex < 0 ? -1 : 0);
  const int sy = ey > 0 ? 1 : (ey < 0 ? -1 : 0);
  const long long ax = std::abs(ex);
  const long long ay = std::abs(ey);
  long long i = 0;  // vertical boundaries crossed
  long long j = 0;  // horizontal boundaries crossed
  for (;;) {
    const bool vertical = 2 * i + 1 < ax;    // another vertical boundary before the end point
    const bool horizontal = 2 * j + 1 < ay;  // another horizontal one
    if (!vertical && !horizontal) return true;
    long long cmp = 0;  // < 0: cross a vertical boundary first, > 0: horizontal, 0: corner
    if (!horizontal) {
      cmp = -1;
    } else if (!vertical) {
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
    if (!on_cell(static_cast<int>(i) * sx, static_cast<int>(j) * sy)) return false;
  }
}

/// One check of a ray, relative to the robot's cell: the ray is blocked here when cells a and
/// b are both occupied. A cell the ray enters has b == a; a corner it passes through has the
/// two cells beside the corner. (Used while building the tables.)
struct Check {
  int a_dx = 0;
  int a_dy = 0;
  int b_dx = 0;
  int b_dy = 0;
  friend bool operator==(const Check&, const Check&) = default;
};

/// A check as stored in the tables (8 bytes): cell a at (dx, dy) from the robot's cell, cell b
/// at (b_dx, b_dy) from a (the two cells beside a corner are diagonal neighbours; (0, 0) for a
/// cell check). For a centre-ray check, bit f of open_faces is set when face ray f of the same
/// target is not implied blocked by this check blocking, so it must be walked; it lives here,
/// next to the check, because the scan reads it right after finding the check blocked.
struct Crossing {
  std::int16_t dx = 0;
  std::int16_t dy = 0;
  std::int8_t b_dx = 0;
  std::int8_t b_dy = 0;
  std::uint8_t open_faces = 0;
  std::uint8_t unused = 0;
};
static_assert(sizeof(Crossing) == 8);

/// A face ray's own checks: crossings[first, first + count). Its leading checks that equal the
/// centre ray's leading checks are not stored again (they are clear whenever the face ray is
/// looked at, see Sensor::scan).
struct FaceRay {
  std::uint32_t first = 0;
  std::uint32_t count = 0;
};

/// One target offset in range: the checks of its centre ray, crossings[first, first + count),
/// and its face rays, faces[face_first, face_first + face_count). 16 bytes: the scan streams
/// through all targets.
struct Target {
  std::uint32_t first = 0;
  std::int16_t dx = 0;
  std::int16_t dy = 0;
  std::uint16_t count = 0;
  std::uint8_t face_count = 0;
  std::uint32_t face_first = 0;
};
static_assert(sizeof(Target) == 16);

/// Largest supported range (cells): offsets and check counts are stored in 16 bits.
constexpr int kMaxRangeCells = 16000;

/// The checks of the ray from the robot's cell centre to (ex, ey) (doubled coordinates) for
/// target offset (dx, dy): the target itself is never checked.
std::vector<Check> ray_checks(int ex, int ey, int dx, int dy) {
  std::vector<Check> out;
  walk_ray(
      ex, ey,
      [&](int x, int y) {
        if (x != dx || y != dy) out.push_back(Check{x, y, x, y});
        return true;
      },
      [&](int ax, int ay, int bx, int by) {
        out.push_back(Check{ax, ay, bx, by});
        return true;
      });
  return out;
}

/// The stored form of `c` (see Crossing).
Crossing compact(const Check& c) {
  Crossing out;
  out.dx = static_cast<std::int16_t>(c.a_dx);
  out.dy = static_cast<std::int16_t>(c.a_dy);
  out.b_dx = static_cast<std::int8_t>(c.b_dx - c.a_dx);
  out.b_dy = static_cast<std::int8_t>(c.b_dy - c.a_dy);
  return out;
}

/// The checks of one ray as a set over the offsets within `r` cells, to ask whether another
/// check implies that this ray is blocked: a check blocks when all of its cells (one, or two
/// for a corner) are occupied, so check c implies the ray is blocked when the ray has a check
/// whose cells are among c's. Dense stamped arrays make assign() and each question O(1) per
/// check, for O(r^2) memory (the order of the tables themselves).
class CheckSet {
 public:
  explicit CheckSet(int r)
      : r_(r + 1),
        side_(2 * r + 3),
        cells_(static_cast<std::size_t>(side_) * static_cast<std::size_t>(side_), 0),
        corners_(2 * cells_.size(), 0) {}

  /// Makes this the set of `ray`'s checks.
  void assign(const std::vector<Check>& ray) {
    ++stamp_;
    for (const Check& c : ray) {
      if (is_cell(c)) {
        cells_[cell(c.a_dx, c.a_dy)] = stamp_;
      } else {
        corners_[corner(c)] = stamp_;
      }
    }
  }

  /// True when `c` blocking implies this ray is blocked.
  [[nodiscard]] bool blocked_by(const Check& c) const {
    return cells_[cell(c.a_dx, c.a_dy)] == stamp_ || cells_[cell(c.b_dx, c.b_dy)] == stamp_ ||
           (!is_cell(c) && corners_[corner(c)] == stamp_);
  }

  /// True when `other` being blocked implies this ray is blocked (every check of `other`
  /// implies it): then this ray being clear implies `other` being clear.
  [[nodiscard]] bool blocked_by(const std::vector<Check>& other) const {
    return std::all_of(other.begin(), other.end(), [&](const Check& c) { return blocked_by(c); });
  }

 private:
  static bool is_cell(const Check& c) { return c.a_dx == c.b_dx && c.a_dy == c.b_dy; }
  [[nodiscard]] std::size_t cell(int x, int y) const {
    return static_cast<std::size_t>(y + r_) * static_cast<std::size_t>(side_) +
           static_cast<std::size_t>(x + r_);
  }
  /// A corner by its point, (a + b) / 2 with odd doubled coordinates a + b, and which diagonal
  /// pair of the four cells around it the check names.
  [[nodiscard]] std::size_t corner(const Check& c) const {
    const int px = (c.a_dx + c.b_dx + 2 * r_ - 1) / 2;
    const int py = (c.a_dy + c.b_dy + 2 * r_ - 1) / 2;
    const bool falling = (c.b_dx - c.a_dx) == (c.b_dy - c.a_dy);
    return (falling ? cells_.size() : 0) + cell(px - r_, py - r_);
  }

  int r_;
  int side_;
  std::uint32_t stamp_ = 0;
  std::vector<std::uint32_t> cells_;
  std::vector<std::uint32_t> corners_;
};

/// Smallest absolute difference between two angles (radians), in [0, pi].
double angle_distance(double a, double b) {
  double d = std::fmod(a - b, 2.0 * M_PI);
  if (d < 0.0) d += 2.0 * M_PI;
  return d > M_PI ? 2.0 * M_PI - d : d;
}

}  // namespace

const ParamDecl<SensorParams>& sensor_params() {
  using P = SensorParams;
  static const ParamDecl<P> kDecl = [] {
    ParamDecl<P> d;
    d.number("range_m", &P::range_m, "sensing radius").above(0).unit("m");
    d.number("fov_deg", &P::fov_deg, "field of view, centred on the heading; 360: omnidirectional")
        .above(0)
        .at_most(360)
        .unit("deg");
    d.number("miss_probability", &P::miss_probability,
             "probability that a visible unknown cell is missed on one scan (the run's \"sensor\" stream)")
        .at_least(0)
        .below(1);
    return d;
  }();
  return kDecl;
}

SensorParams sensor_params_from_json(const nlohmann::json& j, const std::string& where) {
  return sensor_params().read(j, where);
}

void to_json(nlohmann::json& j, const SensorParams& p) { j = sensor_params().write(p); }

struct Sensor::Tables {
  /// In offset-table order.
  std::vector<Target> targets;
  /// Direction to each target's centre (radians, as heading_angle()); read only with a
  /// limited field of view.
  std::vector<double> angles;
  std::vector<Crossing> crossings;
  std::vector<FaceRay> faces;
};

Sensor::Sensor(const SensorParams& params, double resolution_m)
    : params_(params), range_cells_(params.range_m / resolution_m) {
  if (!(resolution_m > 0.0) || !std::isfinite(range_cells_) || range_cells_ < 0.0) {
    throw std::invalid_argument(
        "Sensor: needs resolution_m > 0 and a finite range_m >= 0, got resolution_m = " +
        std::to_string(resolution_m) + ", range_m = " + std::to_string(params.range_m));
  }
  if (range_cells_ > kMaxRangeCells) {
    throw std::invalid_argument("Sensor: range_m / resolution_m = " + std::to_string(range_cells_) +
                                " cells is more than the supported " + std::to_string(kMaxRangeCells));
  }
  auto tables = std::make_shared<Tables>();
  std::vector<Target>& targets = tables->targets;
  std::vector<Crossing>& crossings = tables->crossings;
  // 1. Every offset within range, ordered by squared distance, then row, then column: this is
  //    the "offset-table order" of scan() results and of noise draws.
  const double limit = squared_range_limit(range_cells_);
  const int r = static_cast<int>(std::floor(std::sqrt(limit)));
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      if (static_cast<double>(dx * dx + dy * dy) <= limit) {
        Target t;
        t.dx = static_cast<std::int16_t>(dx);
        t.dy = static_cast<std::int16_t>(dy);
        targets.push_back(t);
      }
    }
  }
  std::sort(targets.begin(), targets.end(), [](const Target& a, const Target& b) {
    const int da = a.dx * a.dx + a.dy * a.dy;
    const int db = b.dx * b.dx + b.dy * b.dy;
    if (da != db) return da < db;
    if (a.dy != b.dy) return a.dy < b.dy;
    return a.dx < b.dx;
  });
  // 2. The checks of each target's centre ray, in walk order, then its face rays that can make
  //    a difference: a face ray implied by the centre ray or by the other face ray (e.g. the
  //    face ray of a target straight ahead, whose checks equal the centre ray's) is dropped.
  //    Each kept face ray stores its checks after its common prefix with the centre ray.
  std::array<CheckSet, 2> sets{CheckSet(r), CheckSet(r)};
  for (Target& t : targets) {
    const int dx = t.dx;
    const int dy = t.dy;
    tables->angles.push_back(std::atan2(static_cast<double>(dy), static_cast<double>(dx)));
    const std::vector<Check> centre = ray_checks(2 * dx, 2 * dy, dx, dy);
    std::array<std::vector<Check>, 2> faces;  // vertical face, horizontal face
    std::array<bool, 2> keep{dx != 0, dy != 0};
    if (keep[0]) faces[0] = ray_checks(2 * dx - (dx > 0 ? 1 : -1), 2 * dy, dx, dy);
    if (keep[1]) faces[1] = ray_checks(2 * dx, 2 * dy - (dy > 0 ? 1 : -1), dx, dy);
    for (std::size_t f = 0; f < 2; ++f) {
      if (!keep[f]) continue;
      sets[f].assign(faces[f]);
      keep[f] = !sets[f].blocked_by(centre);
    }
    if (keep[0] && keep[1]) {
      if (sets[1].blocked_by(faces[0])) {
        keep[1] = false;
      } else if (sets[0].blocked_by(faces[1])) {
        keep[0] = false;
      }
    }

    t.first = static_cast<std::uint32_t>(crossings.size());
    t.count = static_cast<std::uint16_t>(centre.size());
    for (const Check& c : centre) crossings.push_back(compact(c));
    t.face_first = static_cast<std::uint32_t>(tables->faces.size());
    for (std::size_t f = 0; f < 2; ++f) {
      if (!keep[f]) continue;
      const unsigned bit = 1U << t.face_count;
      ++t.face_count;
      const std::vector<Check>& face = faces[f];
      for (std::size_t k = 0; k < centre.size(); ++k) {
        if (!sets[f].blocked_by(centre[k]))
          crossings[t.first + k].open_faces |= static_cast<std::uint8_t>(bit);
      }
      const auto shared = std::mismatch(face.begin(), face.end(), centre.begin(), centre.end()).first;
      tables->faces.push_back(FaceRay{static_cast<std::uint32_t>(crossings.size()),
                                      static_cast<std::uint32_t>(face.end() - shared)});
      std::transform(shared, face.end(), std::back_inserter(crossings), compact);
    }
  }
  crossings.shrink_to_fit();
  revealed_.reserve(targets.size());
  tables_ = std::move(tables);
}

template <typename Skip, typename Opaque, typename Visit>
void Sensor::for_each_visible(int width, int height, Cell at, double heading_rad, Skip&& skip,
                              Opaque&& opaque, Visit&& visit) const {
  const int at_index = at.y * width + at.x;
  const bool limit_fov = params_.fov_deg < 360.0;
  const double half_fov = params_.fov_deg * (M_PI / 360.0) + kAngleSlack;
  // Whether check `c` blocks. Crossed cells lie inside the bounding box of the robot's and the
  // target's cells, so they are on the map.
  const auto blocks = [&](const Crossing& c) {
    const int a = at_index + c.dy * width + c.dx;
    return opaque(a) && opaque(a + c.b_dy * width + c.b_dx);
  };
  const Crossing* const crossings = tables_->crossings.data();
  const FaceRay* const faces = tables_->faces.data();
  const double* const angles = tables_->angles.data();
  const Target* const targets = tables_->targets.data();
  const std::size_t target_count = tables_->targets.size();
  for (std::size_t n = 0; n < target_count; ++n) {
    const Target& t = targets[n];
    // 1. The target must lie on the map and not be skipped.
    const int x = at.x + t.dx;
    const int y = at.y + t.dy;
    if (x < 0 || y < 0 || x >= width || y >= height) continue;
    const int index = at_index + t.dy * width + t.dx;
    if (skip(index)) continue;
    const bool own_cell = t.dx == 0 && t.dy == 0;
    // 2. Field of view (the robot's own cell is always seen).
    if (limit_fov && !own_cell && angle_distance(angles[n], heading_rad) > half_fov) continue;
    // 3. Line of sight: the centre ray; for an opaque target whose centre ray is blocked at
    //    check k, the face rays not implied blocked by check k (its open_faces bits). Such a
    //    face ray does not contain check k, so its common prefix with the centre ray ends
    //    before k and is clear: only its own stored checks remain. (One branch on a rarely set
    //    mask rather than on the target's occupancy, which would mispredict often.)
    const Crossing* c = crossings + t.first;
    std::uint32_t k = 0;
    while (k < t.count && !blocks(c[k])) ++k;
    if (k < t.count) {
      unsigned open = c[k].open_faces;
      open &= 0U - static_cast<unsigned>(opaque(index));
      if (open == 0) continue;
      bool seen = false;
      for (unsigned f = 0; f < t.face_count && !seen; ++f) {
        if (((open >> f) & 1U) == 0) continue;
        const FaceRay& ray = faces[t.face_first + f];
        seen = std::none_of(crossings + ray.first, crossings + ray.first + ray.count, blocks);
      }
      if (!seen) continue;
    }
    visit(index, own_cell);
  }
}

std::span<const int> Sensor::scan(const WorldMap& truth, KnownMap& known, Cell at, double heading_rad,
                                  Rng& rng) {
  revealed_.clear();
  if (!tables_ || !truth.occupied.in_bounds(at)) return {};
  const std::uint8_t* occ = truth.occupied.data().data();
  const bool noisy = params_.miss_probability > 0.0;
  // reveal() below changes cell states in place, never the storage.
  const CellState* const known_state = known.cells().data().data();
  for_each_visible(
      truth.width(), truth.height(), at, heading_rad,
      // Known cells never change, so only unknown targets are looked at.
      [&](int index) { return known_state[index] != CellState::Unknown; },
      [&](int index) { return occ[index] != 0; },
      [&](int index, bool own_cell) {
        // 4. Seeded miss: one draw per visible unknown cell, in table order; the robot's own
        //    cell is never missed.
        if (noisy && !own_cell && uniform01(rng) < params_.miss_probability) return;
        known.reveal(index, occ[index] != 0);
        revealed_.push_back(index);
      });
  return revealed_;
}

ScanCounts Sensor::gain(const KnownMap& known, Cell at, double heading_rad) const {
  ScanCounts counts;
  if (!tables_ || !known.in_bounds(at)) return counts;
  const CellState* const state = known.cells().data().data();
  for_each_visible(
      known.width(), known.height(), at, heading_rad, [](int) { return false; },
      [&](int index) { return state[index] == CellState::Occupied; },
      [&](int index, bool) { ++(state[index] == CellState::Unknown ? counts.unknown : counts.known); });
  return counts;
}

bool Sensor::visible(const WorldMap& truth, Cell at, Cell target) const {
  if (!truth.occupied.in_bounds(at) || !truth.occupied.in_bounds(target)) return false;
  const int dx = target.x - at.x;
  const int dy = target.y - at.y;
  if (static_cast<double>(dx) * dx + static_cast<double>(dy) * dy > squared_range_limit(range_cells_)) {
    return false;
  }
  const auto occupied = [&](int ox, int oy) { return !truth.is_free(Cell{at.x + ox, at.y + oy}); };
  const auto clear = [&](int ex, int ey) {
    return walk_ray(
        ex, ey, [&](int x, int y) { return (x == dx && y == dy) || !occupied(x, y); },
        [&](int ax, int ay, int bx, int by) { return !(occupied(ax, ay) && occupied(bx, by)); });
  };
  if (clear(2 * dx, 2 * dy)) return true;  // centre ray
  if (!occupied(dx, dy)) return false;     // free targets: centre ray only
  const int sx = dx > 0 ? 1 : (dx < 0 ? -1 : 0);
  const int sy = dy > 0 ? 1 : (dy < 0 ? -1 : 0);
  return (dx != 0 && clear(2 * dx - sx, 2 * dy)) || (dy != 0 && clear(2 * dx, 2 * dy - sy));
}

}  // namespace world
}  // namespace fsweep
