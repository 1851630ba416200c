#include "world/sensor.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
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

// ---------------------------------------------------------------------------------------------
// Line of sight by exact shadowcasting: why it decides exactly the ray rule of sensor.hpp.
//
// Frames. Every offset (dx, dy) != (0, 0) is u * U + v * V with 0 <= v <= u in one of eight
// frames (kFrames: U a unit axis vector, V a unit vector perpendicular to it). Frames are
// reflections: they map cells to cells, corners to corners and a target's faces toward the
// robot to faces toward the robot. Below, everything is in one frame, in doubled coordinates
// relative to the robot's centre: cell (u, v) spans (2u-1, 2u+1) x (2v-1, 2v+1); the target
// (t, v) has its centre ray to (2t, 2v), its u-face ray to (2t-1, 2v) and, for v > 0, its
// v-face ray to (2t, 2v-1).
//
// Columns. A ray from the origin with slope s in [0, 1] meets the open interior of a cell
// (c, y), c >= 1, exactly when s lies in the cell's open corner interval
// ((2y-1)/(2c+1), (2y+1)/(2c-1)); it passes the corner (2c-1, Y), Y odd, when s = Y/(2c-1),
// beside the cells (c, (Y-1)/2) and (c-1, (Y+1)/2). In column 0 it meets only the robot's cell
// (at x = 1 it is at height s <= 1: the corner (1, 1) when s = 1). So, for a target (t, v):
// - the centre ray crosses every column c < t entirely and, in column t, only the target,
//   besides the corner (2t-1, 2t-1) when v = t (gcd(2t-1, t) = 1: no other corner with
//   X = 2t-1 has slope v/t);
// - the u-face ray crosses the columns c < t entirely and nothing of column t (its corners
//   have X < 2t-1); for v = t see "Diagonal";
// - the v-face ray crosses the columns c < t entirely and, in column t, only the cell (t, v-1)
//   in front of the face (at x = 2t-1 its height (2v-1)(1 - 1/(2t)) lies in (2v-3, 2v-1) and
//   is no corner: the heights of corners are odd integers).
// Let lit_k be the slopes of [0, 1] that columns 1..k do not block: [0, 1] minus the open
// corner intervals of their opaque cells and minus each corner slope Y/(2c-1), c <= k, whose
// two side cells are both opaque. A target (t, v) is then seen exactly when
// - its centre slope v/t is in lit_{t-1} (for v = t: and not both (t, t-1) and (t-1, t) are
//   opaque), or, for an opaque target,
// - its u-face slope 2v/(2t-1) is in lit_{t-1} (v < t), or
// - its v-face slope (2v-1)/(2t) is in lit_{t-1} and (t, v-1) is not opaque (v > 0).
// Diagonal (v = t): the u-face ray has slope 2t/(2t-1) > 1. It enters (0, 1) (it reaches
// height 1 before x = 1), then (c, c) and (c, c+1) for 1 <= c < t (their intervals contain the
// slope, those of (c, c-1) and (c, c+2) do not), and passes no corner (the slope's numerator in
// lowest terms is even, a corner's is odd). It is clear exactly when 1 is in lit_{t-1} and
// none of (0, 1), (1, 2), ..., (t-1, t) is opaque: 1 is blocked in lit_{t-1} only by an opaque
// (c, c), which the ray enters, or by a corner (2c+1, 2c+1), c < t-1, whose side cell (c, c+1)
// the ray enters.
//
// The sweep. lit_k is a sorted list of disjoint intervals with exact rational ends, each open
// or closed, starting from lit_0 = [0, 1]. Column k first decides its targets on lit_{k-1},
// then cuts its runs of consecutive opaque cells out of it: the run (k, a..b) blocks the open
// interval ((2a-1)/(2k+1), (2b+1)/(2k-1)) (the intervals of neighbouring cells overlap), and
// the corner slope (2b+1)/(2k-1) at its top too when (k-1, b+1) is opaque (a corner below the
// top lies inside the run's interval; one beside a free cell of column k blocks nothing). Each
// candidate slope of a target lies inside the target's open corner interval, so only the
// cells whose interval meets lit_{k-1} are looked at, as targets and as blockers: the work
// follows the cells that can be seen.
//
// Range and map. Every cell a ray to a target T touches (cells entered, cells beside corners,
// and (t-1, t) on the diagonal) lies in the box spanned by the robot's cell and T, so it is on
// the map when T is and no farther from the robot than T. Cells off the map or out of range
// never decide a target on the map and in range, and the sweep treats them as opaque (which
// ends each frame at the range or at the map's edge).
//
// Each target is decided in one frame: one on an axis (v = 0) by the frame whose V points to
// +x or +y, one on a diagonal (v = u) by the frame whose U lies along x.
// ---------------------------------------------------------------------------------------------

/// A slope y / x (x > 0) in a frame (doubled coordinates), compared exactly.
struct Slope {
  std::int64_t y = 0;
  std::int64_t x = 1;
};

/// -1, 0 or 1 as a < b, a == b or a > b (exact: numerators and denominators are at most
/// 2 * kMaxRangeCells + 1).
int compare(Slope a, Slope b) {
  const std::int64_t l = a.y * b.x;
  const std::int64_t r = b.y * a.x;
  return (l > r) - (l < r);
}

/// An interval of slopes, lo <= hi, each end open or closed.
struct Span {
  Slope lo;
  Slope hi;
  bool lo_closed = true;
  bool hi_closed = true;
};

bool contains(const Span& s, Slope q) {
  const int lo = compare(q, s.lo);
  const int hi = compare(q, s.hi);
  return (lo > 0 || (lo == 0 && s.lo_closed)) && (hi < 0 || (hi == 0 && s.hi_closed));
}

/// True when slope q lies in one of the spans of `lit` (sorted, disjoint).
bool contains(const std::vector<Span>& lit, Slope q) {
  auto it = std::partition_point(lit.begin(), lit.end(), [&](const Span& s) { return compare(s.hi, q) < 0; });
  for (; it != lit.end() && compare(it->lo, q) <= 0; ++it) {
    if (contains(*it, q)) return true;
  }
  return false;
}

/// Appends the span <lo, hi> to `out` unless it is empty.
void append(std::vector<Span>& out, Slope lo, bool lo_closed, Slope hi, bool hi_closed) {
  const int c = compare(lo, hi);
  if (c < 0 || (c == 0 && lo_closed && hi_closed)) out.push_back(Span{lo, hi, lo_closed, hi_closed});
}

/// An octant frame: offset = u * (ux, uy) + v * (vx, vy), 0 <= v <= u. owns_axis: decides the
/// offsets with v = 0; owns_diagonal: those with v = u.
struct Frame {
  int ux;
  int uy;
  int vx;
  int vy;
  bool owns_axis;
  bool owns_diagonal;
};

constexpr std::array<Frame, 8> kFrames{{
    {1, 0, 0, 1, true, true},
    {1, 0, 0, -1, false, true},
    {-1, 0, 0, 1, true, true},
    {-1, 0, 0, -1, false, true},
    {0, 1, 1, 0, true, false},
    {0, 1, -1, 0, false, false},
    {0, -1, 1, 0, true, false},
    {0, -1, -1, 0, false, false},
}};

/// The first and last row of column k whose cells' corner intervals can meet the slopes from
/// lo to hi, from slope = y * inverse[x] (inverse[x] = 1.0 / x). Conservative, a row more at
/// most: the numerators are below 2^24, so the product is within 2^-26 of y / x, and y / x is
/// an integer or at least 1 / x > 2^-13 away from one; the floor is off (by one) only for an
/// integer quotient, and both bounds allow for that.
int first_row(Slope lo, int k, const double* inverse) {
  return static_cast<int>(static_cast<double>(lo.y * (2 * k - 1)) * inverse[lo.x]) / 2;
}
int last_row(Slope hi, int k, const double* inverse) {
  return std::min(k, (static_cast<int>(static_cast<double>(hi.y * (2 * k + 1)) * inverse[hi.x]) + 2) / 2);
}

/// The shadowcasting sweep of one frame (see above). `opaque(u, v)` says whether a cell
/// (0 <= v <= u + 1, u <= last_u) blocks; it must be true off the map and out of range.
/// `targets(u)` is the last row of column u holding targets to decide (on the map, in range,
/// v <= u). For each target (u, v) of the frame (v = 0 only when frame.owns_axis, v = u only
/// when frame.owns_diagonal) for which wanted(u, v) holds, calls seen(u, v) when it is
/// visible. inverse[x] = 1.0 / x for x up to 2 * last_u + 1. `lit` and `next` are scratch.
template <typename Opaque, typename Targets, typename Wanted, typename Seen>
void sweep(const Frame& frame, int last_u, Opaque&& opaque, Targets&& targets, Wanted&& wanted, Seen&& seen,
           const double* inverse, std::vector<Span>& lit, std::vector<Span>& next) {
  lit.assign(1, Span{Slope{0, 1}, Slope{1, 1}, true, true});
  bool upper_clear = !opaque(0, 1);  // (0, 1) .. (k-1, k) are not opaque
  for (int k = 1; k <= last_u && !lit.empty(); ++k) {
    const int last_v = std::min(targets(k), frame.owns_diagonal ? k : k - 1);
    int next_v = frame.owns_axis ? 0 : 1;  // the first target not yet decided
    next.clear();
    for (const Span& s : lit) {
      // The cells of column k whose corner interval meets s, and the targets among them.
      const int y0 = first_row(s.lo, k, inverse);
      const int y1 = last_row(s.hi, k, inverse);
      const int t0 = std::max(y0, next_v);
      const int t1 = std::min(y1, last_v);
      next_v = std::max(next_v, t1 + 1);
      // On lit_{k-1}: s holds most candidate slopes, lit is asked for the others.
      const auto lit_at = [&](Slope q) { return contains(s, q) || contains(lit, q); };
      Slope lo = s.lo;  // the part of s above the runs cut so far starts here
      bool lo_closed = s.lo_closed;
      bool cutting = true;  // runs further up may still cut s
      int run = -1;         // first row of the current run of opaque cells, -1: none
      for (int y = y0; y <= y1; ++y) {
        const bool o = opaque(k, y);
        // 1. The target (k, y), on lit_{k-1}.
        if (y >= t0 && y <= t1 && wanted(k, y)) {
          bool visible = lit_at(Slope{y, k}) && (y < k || !(opaque(k, k - 1) && opaque(k - 1, k)));
          if (!visible && o) {
            const std::int64_t y2 = 2 * static_cast<std::int64_t>(y);
            const std::int64_t k2 = 2 * static_cast<std::int64_t>(k);
            visible = y < k ? lit_at(Slope{y2, k2 - 1}) : upper_clear && lit_at(Slope{1, 1});
            if (!visible && y > 0) visible = !opaque(k, y - 1) && lit_at(Slope{y2 - 1, k2});
          }
          if (visible) seen(k, y);
        }
        // 2. lit_k: cut each run of opaque cells (k, run..top) and the corner at its top out of s.
        if (o && run < 0) run = y;
        if (run < 0 || (o && y < y1) || !cutting) continue;
        const int top = o ? y : y - 1;
        const Slope run_lo{2 * run - 1, 2 * k + 1};
        run = -1;
        if (compare(run_lo, s.hi) >= 0) {
          cutting = false;
          continue;
        }
        append(next, lo, lo_closed, run_lo, true);
        const Slope run_hi{2 * top + 1, 2 * k - 1};
        const bool corner = opaque(k - 1, top + 1);
        const int c = compare(run_hi, lo);
        if (c > 0) {
          lo = run_hi;
          lo_closed = !corner;
        } else if (c == 0) {
          lo_closed = lo_closed && !corner;
        }
        cutting = compare(lo, s.hi) <= 0;
      }
      append(next, lo, lo_closed, s.hi, s.hi_closed);
    }
    upper_clear = upper_clear && !opaque(k, k + 1);
    std::swap(lit, next);
  }
}

/// Smallest absolute difference between two angles (radians), in [0, pi].
double angle_distance(double a, double b) {
  double d = std::fmod(a - b, 2.0 * M_PI);
  if (d < 0.0) d += 2.0 * M_PI;
  return d > M_PI ? 2.0 * M_PI - d : d;
}

}  // namespace

std::vector<int> disc_extent(double range_cells) {
  const double limit = squared_range_limit(range_cells);
  const int r = static_cast<int>(std::floor(std::sqrt(limit)));
  const auto in_range = [&](int dx, int dy) { return static_cast<double>(dx * dx + dy * dy) <= limit; };
  std::vector<int> extent(static_cast<std::size_t>(r) + 1, -1);
  for (int u = 0; u <= r; ++u) {
    int v = -1;
    while (v < r && in_range(u, v + 1)) ++v;
    extent[static_cast<std::size_t>(u)] = v;
  }
  return extent;
}

const ParamDecl<SensorParams>& sensor_params() {
  using P = SensorParams;
  static const ParamDecl<P> kDecl = [] {
    ParamDecl<P> d;
    d.number("range_m", &P::range_m, "sensing radius").above(0).unit("m");
    d.number("fov_deg", &P::fov_deg,
             "field of view, centred on the heading (360: omnidirectional); beams span it")
        .above(0)
        .at_most(360)
        .unit("deg");
    d.number("miss_probability", &P::miss_probability,
             "probability that a visible unknown cell is missed on one scan (the run's \"sensor\" stream)")
        .at_least(0)
        .below(1);
    d.choice(
        "model", &P::model, {{"grid", SensorModel::Grid}, {"beams", SensorModel::Beams}},
        "physical model: \"grid\" sees every cell in range and in line of sight; \"beams\" a beam lidar, "
        "`beams` rays over fov_deg, each stopped by the first obstacle (cells between beams unseen)");
    d.integer("beams", &P::beams,
              "number of beams of the \"beams\" model, spread over fov_deg (first and last at +-fov_deg/2; "
              "at 360 evenly, one on the heading)")
        .range(1, kMaxBeams);
    return d;
  }();
  return kDecl;
}

SensorParams sensor_params_from_json(const nlohmann::json& j, const std::string& where) {
  return sensor_params().read(j, where);
}

void to_json(nlohmann::json& j, const SensorParams& p) {
  j = sensor_params().write(p);
  // Absent while default, so that run keys of configurations without a beam sensor stay as
  // they were (as sim's stop_at_cell).
  const SensorParams defaults;
  if (p.model == defaults.model) j.erase("model");
  if (p.beams == defaults.beams) j.erase("beams");
}

/// A target offset from the robot's cell (cells).
struct Offset {
  std::int16_t dx = 0;
  std::int16_t dy = 0;
};

struct Sensor::Tables {
  /// Offsets in range reach r cells along each axis.
  int r = 0;
  /// extent[u], u in [0, r]: the largest v with (u, v) in range (-1: none).
  std::vector<int> extent;
  /// The offsets in range in offset-table order: squared distance, then dy, then dx.
  std::vector<Offset> order;
  /// rank[(dy + r) * (2r + 1) + dx + r]: the position of offset (dx, dy) in `order` (offsets
  /// in range only).
  std::vector<std::uint32_t> rank;
  /// inverse[x] = 1.0 / x for x in [1, 2r + 1] (inverse[0] unused): slope denominators.
  std::vector<double> inverse;
  /// By rank: the direction to the target's centre (radians, as heading_angle()); only with a
  /// limited field of view.
  std::vector<double> angles;
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
  if (params_.model == SensorModel::Beams) {
    beams_ = BeamLidar(params_.beams, params_.fov_deg, squared_range_limit(range_cells_));
    return;
  }
  auto tables = std::make_shared<Tables>();
  const double limit = squared_range_limit(range_cells_);
  const auto in_range = [&](int dx, int dy) { return static_cast<double>(dx * dx + dy * dy) <= limit; };
  tables->extent = disc_extent(range_cells_);
  const int r = static_cast<int>(tables->extent.size()) - 1;
  tables->r = r;
  tables->inverse.assign(2 * static_cast<std::size_t>(r) + 2, 0.0);
  for (std::size_t x = 1; x < tables->inverse.size(); ++x) tables->inverse[x] = 1.0 / static_cast<double>(x);
  // 1. Offset-table order by a counting sort on the squared distance: offsets visited row by
  //    row (dy, then dx, increasing) keep that order within each squared distance.
  const std::size_t side = 2 * static_cast<std::size_t>(r) + 1;
  std::vector<std::uint32_t> start(static_cast<std::size_t>(std::floor(limit)) + 2, 0);
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      if (in_range(dx, dy)) ++start[static_cast<std::size_t>(dx * dx + dy * dy) + 1];
    }
  }
  for (std::size_t d = 1; d < start.size(); ++d) start[d] += start[d - 1];
  tables->order.resize(start.back());
  tables->rank.assign(side * side, 0);
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      if (!in_range(dx, dy)) continue;
      const std::uint32_t n = start[static_cast<std::size_t>(dx * dx) + static_cast<std::size_t>(dy * dy)]++;
      tables->order[n] = Offset{static_cast<std::int16_t>(dx), static_cast<std::int16_t>(dy)};
      tables->rank[static_cast<std::size_t>(dy + r) * side + static_cast<std::size_t>(dx + r)] = n;
    }
  }
  // 2. Directions, for the field of view.
  if (params_.fov_deg < 360.0) {
    tables->angles.reserve(tables->order.size());
    for (const Offset& o : tables->order) {
      tables->angles.push_back(std::atan2(static_cast<double>(o.dy), static_cast<double>(o.dx)));
    }
  }
  seen_bits_.assign((tables->order.size() + 63) / 64, 0);
  tables_ = std::move(tables);
}

std::size_t SightTable::bytes_for(std::size_t cells, std::size_t offsets) {
  const std::size_t per_cell = (offsets + 63) / 64 * sizeof(std::uint64_t) + 1;
  return cells > std::numeric_limits<std::size_t>::max() / per_cell ? std::numeric_limits<std::size_t>::max()
                                                                    : cells * per_cell;
}

SightTable::SightTable(const WorldMap& map, double range_cells, std::size_t offsets)
    : map_(&map),
      range_cells_(range_cells),
      cells_(static_cast<std::size_t>(map.width()) * static_cast<std::size_t>(map.height())),
      words_((offsets + 63) / 64),
      state_(std::make_unique<std::atomic<std::uint8_t>[]>(cells_)),
      bits_(std::make_unique_for_overwrite<std::uint64_t[]>(cells_ * words_)) {}

double Sensor::half_field_of_view() const { return params_.fov_deg * (M_PI / 360.0) + kAngleSlack; }

bool Sensor::outside_view(std::uint32_t rank, double heading_rad) const {
  return rank != 0 && angle_distance(tables_->angles[rank], heading_rad) > half_field_of_view();
}

std::unique_ptr<SightTable> Sensor::sight_table(const WorldMap& truth) const {
  if (!tables_) return nullptr;
  const std::size_t cells =
      static_cast<std::size_t>(truth.width()) * static_cast<std::size_t>(truth.height());
  if (SightTable::bytes_for(cells, tables_->order.size()) > kMaxSightTableBytes) return nullptr;
  return std::unique_ptr<SightTable>(new SightTable(truth, range_cells_, tables_->order.size()));
}

template <typename Skip, typename Opaque, typename Visit>
void Sensor::for_each_visible(int width, int height, Cell at, double heading_rad, bool whole_disc,
                              Skip&& skip, Opaque&& opaque, Visit&& visit) const {
  const Tables& t = *tables_;
  const int at_index = at.y * width + at.x;
  const bool limit_fov = !whole_disc && params_.fov_deg < 360.0;
  const double half_fov = half_field_of_view();
  const std::size_t side = 2 * static_cast<std::size_t>(t.r) + 1;
  // Field of view (the robot's own cell is always seen), then visit.
  const auto target = [&](int index, int dx, int dy) {
    const std::uint32_t rank =
        t.rank[static_cast<std::size_t>(dy + t.r) * side + static_cast<std::size_t>(dx + t.r)];
    if (limit_fov && outside_view(rank, heading_rad)) return;
    visit(index, rank);
  };
  if (!skip(at_index)) target(at_index, 0, 0);
  std::vector<Span> lit;
  std::vector<Span> next;
  for (const Frame& f : kFrames) {
    // A frame whose whole sector lies outside the field of view (by more than rounding can
    // move an angle) has no target to visit.
    if (limit_fov) {
      const double c = std::cos(M_PI / 8.0);
      const double s = std::sin(M_PI / 8.0);
      const double mid = std::atan2(f.uy * c + f.vy * s, f.ux * c + f.vx * s);
      if (angle_distance(mid, heading_rad) > half_fov + M_PI / 8.0 + 1e-6) continue;
    }
    // How far the map reaches along U and V.
    const int u_map = f.ux > 0 ? width - 1 - at.x : f.ux < 0 ? at.x : f.uy > 0 ? height - 1 - at.y : at.y;
    const int v_map = f.vx > 0 ? width - 1 - at.x : f.vx < 0 ? at.x : f.vy > 0 ? height - 1 - at.y : at.y;
    const int step_u = f.ux + f.uy * width;
    const int step_v = f.vx + f.vy * width;
    const auto opaque_at = [&](int u, int v) {
      return v > v_map || v > t.extent[static_cast<std::size_t>(u)] ||
             opaque(at_index + u * step_u + v * step_v);
    };
    const auto targets = [&](int u) { return std::min(v_map, t.extent[static_cast<std::size_t>(u)]); };
    const auto wanted = [&](int u, int v) { return !skip(at_index + u * step_u + v * step_v); };
    const auto seen = [&](int u, int v) {
      target(at_index + u * step_u + v * step_v, u * f.ux + v * f.vx, u * f.uy + v * f.vy);
    };
    sweep(f, std::min(t.r, u_map), opaque_at, targets, wanted, seen, t.inverse.data(), lit, next);
  }
}

std::span<const int> Sensor::scan(const WorldMap& truth, KnownMap& known, Cell at, double heading_rad,
                                  Rng& rng, const std::uint8_t* observable, SightTable* sight) {
  if (params_.model == SensorModel::Beams) {
    return beams_.scan(truth, known, at, heading_rad, params_.miss_probability, rng);
  }
  revealed_.clear();
  if (sight != nullptr &&
      (sight->map_ != &truth || sight->range_cells_ != range_cells_ || sight->words_ != seen_bits_.size())) {
    throw std::invalid_argument("Sensor::scan: the sight table was made for another map or range");
  }
  if (!tables_ || !truth.occupied.in_bounds(at)) return {};
  const int width = truth.width();
  const int at_index = at.y * width + at.x;
  const bool held = sight != nullptr && sight->filled(at_index);
  // 0. Nothing to reveal when every cell in range on the map is known, or never seen from
  //    anywhere (a robot standing in explored space): a byte search along the rows of the disc
  //    costs less than the sweep (or than filling the sight table's row).
  if (!held && all_known(known, at, observable)) return revealed_;
  // 1. With a sight table: its row, filled by one sweep of every target the first time.
  if (sight != nullptr) {
    reveal_ranks<true>(truth, known, at, heading_rad, rng, sight_row(*sight, truth, at), 0, sight->words_);
    return revealed_;
  }
  const std::uint8_t* occ = truth.occupied.data().data();
  const CellState* const known_state = known.cells().data().data();
  std::uint64_t* const bits = seen_bits_.data();
  std::size_t first_word = seen_bits_.size();
  std::size_t end_word = 0;
  const auto take = [&](std::uint32_t rank) {
    const std::size_t w = rank / 64;
    bits[w] |= std::uint64_t{1} << (rank % 64);
    first_word = std::min(first_word, w);
    end_word = std::max(end_word, w + 1);
  };
  // 2. A small disc without obstacles on the true map: every target in it is visible (a ray
  //    between the centres of two cells in range enters, or touches at a corner, only cells of
  //    the bounding box of those two, all in range and on the map, so nothing blocks it): the
  //    targets are those on the map, unknown and in the field of view, and no sweep is needed.
  if (tables_->r <= kOpenDiscMaxCells && open_disc(truth, at)) {
    const Offset* const order = tables_->order.data();
    const bool limit_fov = params_.fov_deg < 360.0;
    const auto rank_count = static_cast<std::uint32_t>(tables_->order.size());
    for (std::uint32_t rank = 0; rank < rank_count; ++rank) {
      const int x = at.x + order[rank].dx;
      const int y = at.y + order[rank].dy;
      if (x < 0 || y < 0 || x >= width || y >= truth.height()) continue;
      if (known_state[y * width + x] != CellState::Unknown) continue;
      if (limit_fov && outside_view(rank, heading_rad)) continue;
      take(rank);
    }
  } else {
    // 3. The visible targets that are still unknown, as bits by rank.
    for_each_visible(
        truth.width(), truth.height(), at, heading_rad, false,
        // Known cells never change, so only unknown targets are looked at.
        [&](int index) { return known_state[index] != CellState::Unknown; },
        [&](int index) { return occ[index] != 0; }, [&](int, std::uint32_t rank) { take(rank); });
  }
  // 4. Reveal them in offset-table order, then clear the bits for the next scan.
  reveal_ranks<false>(truth, known, at, heading_rad, rng, bits, first_word, end_word);
  if (first_word < end_word) std::fill(bits + first_word, bits + end_word, 0);
  return revealed_;
}

const std::uint64_t* Sensor::sight_row(SightTable& sight, const WorldMap& truth, Cell at) {
  const auto i = static_cast<std::size_t>(at.y) * static_cast<std::size_t>(truth.width()) +
                 static_cast<std::size_t>(at.x);
  std::uint64_t* const row = sight.bits_.get() + i * sight.words_;
  // A plain load first: a compare-exchange takes the state's cache line even when it fails.
  std::uint8_t state = sight.state_[i].load(std::memory_order_acquire);
  if (state == SightTable::kFilled) return row;
  const bool mine =
      state == SightTable::kEmpty &&
      sight.state_[i].compare_exchange_strong(state, SightTable::kFilling, std::memory_order_acquire);
  if (!mine && state == SightTable::kFilled) return row;
  sight_scratch_.resize(sight.words_);
  std::uint64_t* const out = mine ? row : sight_scratch_.data();
  std::fill(out, out + sight.words_, 0);
  const std::uint8_t* occ = truth.occupied.data().data();
  try {
    for_each_visible(
        truth.width(), truth.height(), at, 0.0, true, [](int) { return false; },
        [&](int index) { return occ[index] != 0; },
        [&](int, std::uint32_t rank) { out[rank / 64] |= std::uint64_t{1} << (rank % 64); });
  } catch (...) {  // the sweep's scratch could not grow: the row is left to a later scan
    if (mine) sight.state_[i].store(SightTable::kEmpty, std::memory_order_release);
    throw;
  }
  if (mine) sight.state_[i].store(SightTable::kFilled, std::memory_order_release);
  return out;
}

template <bool kEveryTarget>
void Sensor::reveal_ranks(const WorldMap& truth, KnownMap& known, Cell at, double heading_rad, Rng& rng,
                          const std::uint64_t* bits, std::size_t first_word, std::size_t end_word) {
  const Offset* const order = tables_->order.data();
  const std::uint8_t* occ = truth.occupied.data().data();
  const CellState* const known_state = known.cells().data().data();
  const int width = truth.width();
  const int at_index = at.y * width + at.x;
  const bool noisy = params_.miss_probability > 0.0;
  const bool limit_fov = kEveryTarget && params_.fov_deg < 360.0;
  for (std::size_t w = first_word; w < end_word; ++w) {
    for (std::uint64_t word = bits[w]; word != 0; word &= word - 1) {
      const auto rank = static_cast<std::uint32_t>(w * 64 + static_cast<std::size_t>(std::countr_zero(word)));
      const int index = at_index + order[rank].dy * width + order[rank].dx;
      if (kEveryTarget && known_state[index] != CellState::Unknown) continue;
      if (limit_fov && outside_view(rank, heading_rad)) continue;
      // Seeded miss: one draw per visible unknown cell, in table order; the robot's own cell is
      // never missed.
      if (noisy && rank != 0 && uniform01(rng) < params_.miss_probability) continue;
      known.reveal(index, Cell{at.x + order[rank].dx, at.y + order[rank].dy}, occ[index] != 0);
      revealed_.push_back(index);
    }
  }
}

namespace {

/// True when `test(first, count)` holds for every row of the disc of offsets in range around
/// `at`, clipped to a width x height grid: the row's `count` cells from index `first` on.
/// extent[u]: the largest v with (u, v) in range (Sensor::Tables).
template <typename RowTest>
bool every_disc_row(const std::vector<int>& extent, int width, int height, Cell at, RowTest&& test) {
  const int r = static_cast<int>(extent.size()) - 1;
  for (int dy = -r; dy <= r; ++dy) {
    const int y = at.y + dy;
    if (y < 0 || y >= height) continue;
    const int reach = extent[static_cast<std::size_t>(std::abs(dy))];
    const int x0 = std::max(0, at.x - reach);
    const int x1 = std::min(width - 1, at.x + reach);
    if (x0 <= x1 &&
        !test(static_cast<std::ptrdiff_t>(y) * width + x0, static_cast<std::size_t>(x1 - x0) + 1)) {
      return false;
    }
  }
  return true;
}

}  // namespace

bool Sensor::open_disc(const WorldMap& truth, Cell at) const {
  const std::uint8_t* const occ = truth.occupied.data().data();
  return every_disc_row(tables_->extent, truth.width(), truth.height(), at,
                        [occ](std::ptrdiff_t first, std::size_t count) {
                          return std::all_of(occ + first, occ + first + static_cast<std::ptrdiff_t>(count),
                                             [](std::uint8_t o) { return o == 0; });
                        });
}

bool Sensor::all_known(const KnownMap& known, Cell at, const std::uint8_t* observable) const {
  static_assert(static_cast<int>(CellState::Unknown) == 0 && sizeof(CellState) == 1);
  const CellState* const state = known.cells().data().data();
  return every_disc_row(tables_->extent, known.width(), known.height(), at,
                        [state, observable](std::ptrdiff_t first, std::size_t count) {
                          const CellState* const row = state + first;
                          if (observable == nullptr) return std::memchr(row, 0, count) == nullptr;
                          // Whether the row holds an unknown cell some scan could see, over the
                          // whole row without branches (a memchr for each unknown cell would run
                          // once per cell of a building's inside).
                          const std::uint8_t* const seeable = observable + first;
                          unsigned unseen = 0;
                          for (std::size_t i = 0; i < count; ++i) {
                            unseen |= static_cast<unsigned>(row[i] == CellState::Unknown) &
                                      static_cast<unsigned>(seeable[i] != 0);
                          }
                          return unseen == 0;
                        });
}

ScanCounts Sensor::gain(const KnownMap& known, Cell at, double heading_rad) const {
  if (params_.model == SensorModel::Beams) return beams_.gain(known, at, heading_rad);
  ScanCounts counts;
  if (!tables_ || !known.in_bounds(at)) return counts;
  const CellState* const state = known.cells().data().data();
  for_each_visible(
      known.width(), known.height(), at, heading_rad, false, [](int) { return false; },
      [&](int index) { return state[index] == CellState::Occupied; },
      [&](int index, std::uint32_t) {
        ++(state[index] == CellState::Unknown ? counts.unknown : counts.known);
      });
  return counts;
}

namespace {

/// The ray rule of the file comment for a ray from the robot's cell centre to the end point
/// (ex, ey) (doubled coordinates, walk_ray()) towards the target at (dx, dy) (cells, relative):
/// clear when no cell it enters but the target is occupied(x, y) and no corner it passes has
/// both side cells occupied.
template <typename Occupied>
bool ray_clear(int ex, int ey, int dx, int dy, Occupied&& occupied) {
  return walk_ray(
      ex, ey, [&](int x, int y) { return (x == dx && y == dy) || !occupied(x, y); },
      [&](int ax, int ay, int bx, int by) { return !(occupied(ax, ay) && occupied(bx, by)); });
}

}  // namespace

bool centre_ray_clear(const KnownMap& known, Cell at, Cell target) {
  const int dx = target.x - at.x;
  const int dy = target.y - at.y;
  return ray_clear(2 * dx, 2 * dy, dx, dy, [&](int ox, int oy) {
    const Cell c{at.x + ox, at.y + oy};
    return !known.in_bounds(c) || known.state(c) == CellState::Occupied;
  });
}

bool Sensor::visible(const WorldMap& truth, Cell at, Cell target, double heading_rad) const {
  if (params_.model == SensorModel::Beams) return beams_.visible(truth, at, target, heading_rad);
  if (!truth.occupied.in_bounds(at) || !truth.occupied.in_bounds(target)) return false;
  const int dx = target.x - at.x;
  const int dy = target.y - at.y;
  if (static_cast<double>(dx) * dx + static_cast<double>(dy) * dy > squared_range_limit(range_cells_)) {
    return false;
  }
  const auto occupied = [&](int ox, int oy) { return !truth.is_free(Cell{at.x + ox, at.y + oy}); };
  const auto clear = [&](int ex, int ey) { return ray_clear(ex, ey, dx, dy, occupied); };
  if (clear(2 * dx, 2 * dy)) return true;  // centre ray
  if (!occupied(dx, dy)) return false;     // free targets: centre ray only
  const int sx = dx > 0 ? 1 : (dx < 0 ? -1 : 0);
  const int sy = dy > 0 ? 1 : (dy < 0 ? -1 : 0);
  return (dx != 0 && clear(2 * dx - sx, 2 * dy)) || (dy != 0 && clear(2 * dx, 2 * dy - sy));
}

}  // namespace world
}  // namespace fsweep
