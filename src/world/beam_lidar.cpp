#include "world/beam_lidar.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

namespace fsweep {
inline namespace world {
namespace {

/// A beam passes through a grid corner when its crossings of the corner's vertical and
/// horizontal boundary lines lie within this distance of each other along the beam (cells):
/// exact in real arithmetic for the diagonal beams, which double rounding would otherwise
/// split into a crossing a hair before the other.
constexpr double kBeamCornerSlack = 1e-9;
/// Widening of the directions that can meet a target's square in visible() (radians): more
/// than the corner slack turns into at the nearest target (kBeamCornerSlack / 0.5 cells), so
/// no beam that enters the target is left out; beams let in by it are walked and decide.
constexpr double kBeamAngleSlack = 1e-6;
constexpr double kTwoPi = 2.0 * M_PI;

}  // namespace

BeamLidar::BeamLidar(int beams, double fov_deg, double squared_range_limit) {
  if (beams < 1 || !(fov_deg > 0.0 && fov_deg <= 360.0) || !std::isfinite(squared_range_limit) ||
      squared_range_limit < 0.0) {
    throw std::invalid_argument(
        "BeamLidar: needs beams >= 1, fov_deg in (0, 360] and a finite range, got beams = " +
        std::to_string(beams) + ", fov_deg = " + std::to_string(fov_deg));
  }
  squared_limit_ = squared_range_limit;
  length_ = std::sqrt(squared_range_limit);
  reach_ = static_cast<int>(std::floor(length_));
  // Beam directions relative to the heading (sensor.hpp): a full circle without repeating the
  // first beam, one beam on the heading; otherwise first and last at -+fov/2.
  auto offsets = std::make_shared<std::vector<double>>(static_cast<std::size_t>(beams));
  const auto n = static_cast<double>(beams);
  if (fov_deg >= 360.0) {
    const int on_heading = beams / 2;  // floor(n/2)
    step_rad_ = kTwoPi / n;
    first_rad_ = kTwoPi * static_cast<double>(-on_heading) / n;
    for (int i = 0; i < beams; ++i) {
      (*offsets)[static_cast<std::size_t>(i)] = kTwoPi * static_cast<double>(i - on_heading) / n;
    }
  } else if (beams > 1) {
    const double fov_rad = fov_deg * (M_PI / 180.0);
    step_rad_ = fov_rad / (n - 1.0);
    first_rad_ = -0.5 * fov_rad;
    for (int i = 0; i < beams; ++i) {
      (*offsets)[static_cast<std::size_t>(i)] = fov_rad * (static_cast<double>(i) / (n - 1.0) - 0.5);
    }
  }  // one beam, fov < 360: along the heading (offset 0, step 0)
  offsets_ = std::move(offsets);
}

template <typename Blocked, typename Enter>
void BeamLidar::walk(int width, int height, Cell at, double heading_rad, int beam, Blocked&& blocked,
                     Enter&& enter) const {
  const double angle = heading_rad + offset_rad(beam);
  const double ux = std::cos(angle);
  const double uy = std::sin(angle);
  const auto on_map = [&](int dx, int dy) {
    return at.x + dx >= 0 && at.x + dx < width && at.y + dy >= 0 && at.y + dy < height;
  };
  const auto index = [&](int dx, int dy) { return (at.y + dy) * width + at.x + dx; };
  const auto obstacle = [&](int dx, int dy) { return !on_map(dx, dy) || blocked(index(dx, dy)); };
  // A cell the beam enters: passed on when it is on the map and in range.
  const auto reach = [&](int dx, int dy) {
    if (!on_map(dx, dy) || static_cast<double>(dx * dx + dy * dy) > squared_limit_) return true;
    return static_cast<bool>(enter(index(dx, dy), dx, dy));
  };
  if (!reach(0, 0)) return;  // the robot's own cell: entered at t = 0, never blocks
  const int sx = ux > 0.0 ? 1 : (ux < 0.0 ? -1 : 0);
  const int sy = uy > 0.0 ? 1 : (uy < 0.0 ? -1 : 0);
  constexpr double kNever = std::numeric_limits<double>::infinity();
  const double inv_x = sx != 0 ? 1.0 / std::abs(ux) : kNever;
  const double inv_y = sy != 0 ? 1.0 / std::abs(uy) : kNever;
  int cx = 0;
  int cy = 0;
  for (;;) {
    // 1. The beam leaves cell (cx, cy) through its vertical side at t = (|cx| + 1/2) / |ux|,
    //    through its horizontal side at t = (|cy| + 1/2) / |uy| (t: cells along the beam).
    const double tx = (std::abs(cx) + 0.5) * inv_x;
    const double ty = (std::abs(cy) + 0.5) * inv_y;
    if (std::min(tx, ty) > length_) return;
    if (std::abs(tx - ty) <= kBeamCornerSlack) {
      // 2. Through a corner: the two cells beside it are touched at that point only; both
      //    obstacles block the beam there, and both are entered (in this order).
      if (obstacle(cx + sx, cy) && obstacle(cx, cy + sy)) {
        if (reach(cx + sx, cy)) reach(cx, cy + sy);
        return;
      }
      cx += sx;
      cy += sy;
    } else if (tx < ty) {
      cx += sx;
    } else {
      cy += sy;
    }
    // 3. Enter the next cell; the first obstacle is entered and ends the beam.
    if (!reach(cx, cy) || obstacle(cx, cy)) return;
  }
}

bool BeamLidar::mark(int dx, int dy) const {
  const std::size_t side = 2 * static_cast<std::size_t>(reach_) + 1;
  if (marks_.empty()) marks_.assign((side * side + 63) / 64, 0);
  const std::size_t bit =
      static_cast<std::size_t>(dy + reach_) * side + static_cast<std::size_t>(dx + reach_);
  std::uint64_t& word = marks_[bit / 64];
  const std::uint64_t mask = std::uint64_t{1} << (bit % 64);
  if ((word & mask) != 0) return false;
  word |= mask;
  marked_.push_back(static_cast<std::uint32_t>(bit));
  return true;
}

void BeamLidar::clear_marks() const {
  for (const std::uint32_t bit : marked_) marks_[bit / 64] = 0;
  marked_.clear();
}

std::span<const int> BeamLidar::scan(const WorldMap& truth, KnownMap& known, Cell at, double heading_rad,
                                     double miss_probability, Rng& rng) {
  revealed_.clear();
  if (!offsets_ || !truth.occupied.in_bounds(at)) return revealed_;
  const std::uint8_t* const occ = truth.occupied.data().data();
  const CellState* const state = known.cells().data().data();
  const bool noisy = miss_probability > 0.0;
  const auto blocked = [occ](int index) { return occ[index] != 0; };
  for (int b = 0; b < beams(); ++b) {
    walk(truth.width(), truth.height(), at, heading_rad, b, blocked, [&](int index, int dx, int dy) {
      // Known cells, those revealed by this scan included, have nothing to reveal.
      if (state[index] != CellState::Unknown) return true;
      // Seeded miss: one draw per unknown cell, at its first visit (a missed cell is marked
      // and not drawn again on this scan); the robot's own cell is never missed.
      if (noisy && (dx != 0 || dy != 0) && (!mark(dx, dy) || uniform01(rng) < miss_probability)) return true;
      known.reveal(index, occ[index] != 0);
      revealed_.push_back(index);
      return true;
    });
  }
  clear_marks();
  return revealed_;
}

ScanCounts BeamLidar::gain(const KnownMap& known, Cell at, double heading_rad) const {
  ScanCounts counts;
  if (!offsets_ || !known.in_bounds(at)) return counts;
  const CellState* const state = known.cells().data().data();
  const auto blocked = [state](int index) { return state[index] == CellState::Occupied; };
  for (int b = 0; b < beams(); ++b) {
    walk(known.width(), known.height(), at, heading_rad, b, blocked, [&](int index, int dx, int dy) {
      if (mark(dx, dy)) ++(state[index] == CellState::Unknown ? counts.unknown : counts.known);
      return true;
    });
  }
  clear_marks();
  return counts;
}

bool BeamLidar::visible(const WorldMap& truth, Cell at, Cell target, double heading_rad) const {
  if (!offsets_ || !truth.occupied.in_bounds(at) || !truth.occupied.in_bounds(target)) return false;
  const int dx = target.x - at.x;
  const int dy = target.y - at.y;
  if (static_cast<double>(dx) * dx + static_cast<double>(dy) * dy > squared_limit_) return false;
  if (dx == 0 && dy == 0) return true;
  const std::uint8_t* const occ = truth.occupied.data().data();
  const auto blocked = [occ](int index) { return occ[index] != 0; };
  const auto reaches = [&](int b) {
    bool seen = false;
    walk(truth.width(), truth.height(), at, heading_rad, b, blocked, [&](int, int x, int y) {
      seen = seen || (x == dx && y == dy);
      return !seen;
    });
    return seen;
  };
  if (step_rad_ == 0.0) return reaches(0);  // one beam
  // 1. The directions that meet the target's square lie between those of its corners, within
  //    a quarter turn of its centre's direction (the square does not hold the robot's centre).
  const double centre = std::atan2(static_cast<double>(dy), static_cast<double>(dx));
  double lo = 0.0;
  double hi = 0.0;
  for (const double cx : {dx - 0.5, dx + 0.5}) {
    for (const double cy : {dy - 0.5, dy + 0.5}) {
      const double d = std::remainder(std::atan2(cy, cx) - centre, kTwoPi);
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
  }
  // 2. The beams with those directions: beam i's offset is first + i step (up to rounding,
  //    which the slack covers), c the centre's offset from beam 0 in [0, 2 pi).
  double c = std::fmod(centre - heading_rad - first_rad_, kTwoPi);
  if (c < 0.0) c += kTwoPi;
  const int last = beams() - 1;
  for (const double turn : {-kTwoPi, 0.0, kTwoPi}) {
    const double from = std::ceil((c + lo + turn - kBeamAngleSlack) / step_rad_);
    const double to = std::floor((c + hi + turn + kBeamAngleSlack) / step_rad_);
    if (to < 0.0 || from > last) continue;
    for (int b = std::max(0, static_cast<int>(from)); b <= std::min(last, static_cast<int>(to)); ++b) {
      if (reaches(b)) return true;
    }
  }
  return false;
}

}  // namespace world
}  // namespace fsweep
