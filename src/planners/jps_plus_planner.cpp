#include "planners/jps_plus_planner.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "planners/jump_points.hpp"

namespace fsweep {
inline namespace planners {
// A namespace of its own around the file's helpers: unity builds put this file into one
// translation unit with jps_planner.cpp and lattice_planner.cpp, whose helpers share names.
namespace jps_plus_detail {
namespace {

constexpr int kHeadings = 8;
constexpr int kEast = 0;
constexpr int kSouthEast = 1;
constexpr int kSouth = 2;
constexpr int kSouthWest = 3;
constexpr int kWest = 4;
constexpr int kNorthWest = 5;
constexpr int kNorth = 6;
constexpr int kNorthEast = 7;
static_assert(kDirections[kSouthEast].x == 1 && kDirections[kSouthEast].y == 1 &&
              kDirections[kNorth].y == -1);

/// Longest distance a table entry holds (see extend()).
constexpr int kMaxDistance = std::numeric_limits<std::int16_t>::max();

/// The heading (grid.hpp) of the unit step (dx, dy), each in -1..1, not both 0.
constexpr int heading_index(int dx, int dy) {
  constexpr std::array<int, 9> kByStep{kNorthWest, kNorth,     kNorthEast, kWest,     -1,
                                       kEast,      kSouthWest, kSouth,     kSouthEast};
  const int step = (dy + 1) * 3 + dx + 1;
  return kByStep[static_cast<std::size_t>(step)];
}

/// A cell's distance in some heading from that of the next cell along it, `next`, one step
/// ahead (Rabin's recurrence): 1 if the next cell is a jump point, else one step more than
/// `next` (positive: the same jump point; 0 or negative: one more free step before the wall).
/// Where that would pass kMaxDistance the next cell becomes a jump point instead: an extra stop
/// from which the search goes on in the same heading.
constexpr std::int16_t extend(std::int16_t next, bool next_is_jump_point) {
  if (next_is_jump_point || next == kMaxDistance || next == -kMaxDistance) return 1;
  return static_cast<std::int16_t>(next > 0 ? next + 1 : next - 1);
}

/// Fills a JumpTable's distances for one known map under one corner rule (`kCut`, the rules of
/// jps_planner.hpp's file comment).
template <bool kCut>
class TableBuilder {
 public:
  TableBuilder(const KnownMap& known, std::vector<std::uint8_t>& padded_free,
               std::vector<std::int16_t>& distances)
      : width_(known.width()),
        height_(known.height()),
        padded_width_(known.width() + 2),
        padded_free_(padded_free),
        distances_(distances) {
    const std::size_t cells = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
    padded_free_.assign(static_cast<std::size_t>(padded_width_) * static_cast<std::size_t>(height_ + 2), 0);
    const CellState* states = known.cells().data().data();
    for (int y = 0; y < height_; ++y) {
      for (int x = 0; x < width_; ++x) {
        padded_free_[padded(x, y)] = static_cast<std::uint8_t>(states[y * width_ + x] == CellState::Free);
      }
    }
    distances_.resize(cells * kHeadings);
  }

  /// Every distance, each heading after the ones it reads: rows north to south for the east,
  /// west and north headings and then the north diagonals (which read the row above); rows south
  /// to north for south and the south diagonals.
  void build() {
    for (int y = 0; y < height_; ++y) {
      for (int x = width_ - 1; x >= 0; --x) straight(x, y, kEast);
      for (int x = 0; x < width_; ++x) straight(x, y, kWest);
      for (int x = 0; x < width_; ++x) {
        straight(x, y, kNorth);
        diagonal(x, y, kNorthEast);
        diagonal(x, y, kNorthWest);
      }
    }
    for (int y = height_ - 1; y >= 0; --y) {
      for (int x = 0; x < width_; ++x) {
        straight(x, y, kSouth);
        diagonal(x, y, kSouthEast);
        diagonal(x, y, kSouthWest);
      }
    }
  }

 private:
  [[nodiscard]] std::size_t padded(int x, int y) const {
    return static_cast<std::size_t>(y + 1) * static_cast<std::size_t>(padded_width_) +
           static_cast<std::size_t>(x + 1);
  }
  /// Known free; false one cell past the grid's edge.
  [[nodiscard]] bool free(int x, int y) const { return padded_free_[padded(x, y)] != 0; }
  [[nodiscard]] std::int16_t& at(int x, int y, int heading) {
    return distances_[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
                       static_cast<std::size_t>(x)) *
                          kHeadings +
                      static_cast<std::size_t>(heading)];
  }

  /// (x, y), entered by the straight step s from a free cell, has a forced neighbour (without
  /// corner cutting: a side cell free whose cell behind is not; with it: a side cell blocked
  /// whose cell ahead is free).
  [[nodiscard]] bool straight_jump_point(int x, int y, Cell s) const {
    for (const Cell q : {Cell{s.y, s.x}, Cell{-s.y, -s.x}}) {
      if constexpr (kCut) {
        if (!free(x + q.x, y + q.y) && free(x + s.x + q.x, y + s.y + q.y)) return true;
      } else {
        if (free(x + q.x, y + q.y) && !free(x - s.x + q.x, y - s.y + q.y)) return true;
      }
    }
    return false;
  }
  /// (x, y), entered by the diagonal step s, has a forced neighbour (corner cutting only).
  [[nodiscard]] bool diagonal_forced(int x, int y, Cell s) const {
    return (!free(x - s.x, y) && free(x - s.x, y + s.y)) || (!free(x, y - s.y) && free(x + s.x, y - s.y));
  }

  /// The distance of (x, y) in the straight heading from its next cell's.
  void straight(int x, int y, int heading) {
    const Cell s = kDirections[static_cast<std::size_t>(heading)];
    const int nx = x + s.x;
    const int ny = y + s.y;
    std::int16_t& d = at(x, y, heading);
    if (!free(x, y) || !free(nx, ny)) {
      d = 0;
      return;
    }
    d = extend(at(nx, ny, heading), straight_jump_point(nx, ny, s));
  }
  /// The distance of (x, y) in the diagonal heading: the next cell is a jump point if it has a
  /// forced neighbour or a straight jump point along either component.
  void diagonal(int x, int y, int heading) {
    const Cell s = kDirections[static_cast<std::size_t>(heading)];
    const int nx = x + s.x;
    const int ny = y + s.y;
    std::int16_t& d = at(x, y, heading);
    if (!free(x, y) || !free(nx, ny) || (!kCut && (!free(nx, y) || !free(x, ny)))) {
      d = 0;
      return;
    }
    bool jump_point = at(nx, ny, heading_index(s.x, 0)) > 0 || at(nx, ny, heading_index(0, s.y)) > 0;
    if constexpr (kCut) jump_point = jump_point || diagonal_forced(nx, ny, s);
    d = extend(at(nx, ny, heading), jump_point);
  }

  int width_;
  int height_;
  int padded_width_;
  std::vector<std::uint8_t>& padded_free_;
  std::vector<std::int16_t>& distances_;
};

/// Search environment of one JPS+ query (the BestFirstSearch contract of grid_search.hpp): as
/// `jps`'s (jps_planner.cpp), states are cell indices of which only jump points are opened, the
/// headings to jump in pruned by the direction of arrival (read from the parent in `search`), but
/// each jump is a table read plus the goal checks of the file comment of jps_plus_planner.hpp.
template <bool kCut>
class JumpTableEnvironment {
 public:
  using Cost = OctileCost;
  JumpTableEnvironment(const KnownMap& known, const std::int16_t* distances, Cell goal,
                       const OctileSearch& search)
      : cells_(known.cells().data().data()),
        distances_(distances),
        width_(known.width()),
        height_(known.height()),
        goal_(goal),
        goal_index_(known.index(goal)),
        search_(search) {
    for (int h = 0; h < kHeadings; ++h) {
      const Cell d = kDirections[static_cast<std::size_t>(h)];
      offsets_[static_cast<std::size_t>(h)] = d.y * width_ + d.x;
    }
  }

  [[nodiscard]] int state_count() const { return width_ * height_; }
  [[nodiscard]] Cost heuristic(int state) const { return octile_cost(cell_of(state), goal_); }
  [[nodiscard]] Visit visit(int state, double /*g*/) const {
    return state == goal_index_ ? Visit::Goal : Visit::Expand;
  }

  template <typename Sink>
  void for_each_successor(int state, Sink&& sink) const {
    const Cell at = cell_of(state);
    std::array<int, kHeadings> headings{};
    int count = 0;
    const auto add = [&](int dx, int dy) {
      headings[static_cast<std::size_t>(count++)] = heading_index(dx, dy);
    };
    const int parent = search_.parent(state);
    jump_points::pruned_directions<kCut>(
        at, parent < 0 ? std::nullopt : std::optional<Cell>(cell_of(parent)),
        [this](int x, int y) { return is_free(x, y); }, add);
    // Each successor: `next`, reached at `cost`. A* often expands a successor soon after opening
    //    it (ties go to the larger g), so its table line is fetched meanwhile: the table is too
    //    large to stay in cache on large maps (measured on a 1024 x 1024 map: queries 0.7x the
    //    time without).
    const auto open = [&](int next, Cost cost) {
      __builtin_prefetch(distances_ + static_cast<std::ptrdiff_t>(next) * kHeadings);
      sink(next, cost);
    };
    for (int k = 0; k < count; ++k) {
      const auto h = static_cast<std::size_t>(headings[static_cast<std::size_t>(k)]);
      const Cell s = kDirections[h];
      if (s.x == 0 || s.y == 0) {
        const int steps = straight_steps(state, at, h);
        if (steps > 0) open(state + steps * offsets_[h], Cost{steps, 0});
      } else {
        follow_diagonal(state, at, h, open);
      }
    }
  }

 private:
  /// The steps of the straight jump from `state` (at `at`) in heading h: to the goal when it
  /// lies ahead on the line within reach, else the table's distance (<= 0: no jump point).
  [[nodiscard]] int straight_steps(int state, Cell at, std::size_t h) const {
    const Cell s = kDirections[h];
    const int d = distances_[static_cast<std::ptrdiff_t>(state) * kHeadings + static_cast<std::ptrdiff_t>(h)];
    const int gx = goal_.x - at.x;
    const int gy = goal_.y - at.y;
    const int ahead = s.x * gx + s.y * gy;
    const bool goal_ahead = (s.x == 0 ? gx : gy) == 0 && ahead > 0 && ahead <= (d > 0 ? d : -d);
    return goal_ahead ? ahead : d;
  }
  /// Opens the successors of `state` (at `at`) along the diagonal heading h, as `jps` does (its
  /// online pruning, jps_planner.hpp): from each diagonal jump point the table names, the jump
  /// points of its straight jumps along the two components, reached through it, and on to the
  /// next one. The goal's row or column within reach in the goal's quadrant (Rabin's target
  /// jump point) and, with corner cutting, a diagonal jump point with a forced neighbour are
  /// opened themselves and end the jump.
  template <typename Open>
  void follow_diagonal(int state, Cell at, std::size_t h, const Open& open) const {
    const Cell s = kDirections[h];
    const auto across = static_cast<std::size_t>(heading_index(s.x, 0));
    const auto along = static_cast<std::size_t>(heading_index(0, s.y));
    int diagonal = 0;  // steps from the expanded state
    while (true) {
      const int d =
          distances_[static_cast<std::ptrdiff_t>(state) * kHeadings + static_cast<std::ptrdiff_t>(h)];
      const int gx = goal_.x - at.x;
      const int gy = goal_.y - at.y;
      const int to_goal_line = std::min(gx * s.x, gy * s.y);
      if (sign_of(gx) == s.x && sign_of(gy) == s.y && to_goal_line <= (d > 0 ? d : -d)) {
        return open(state + to_goal_line * offsets_[h], Cost{0, diagonal + to_goal_line});
      }
      if (d <= 0) return;
      state += d * offsets_[h];
      at = Cell{at.x + d * s.x, at.y + d * s.y};
      diagonal += d;
      if constexpr (kCut) {
        if ((!is_free(at.x - s.x, at.y) && is_free(at.x - s.x, at.y + s.y)) ||
            (!is_free(at.x, at.y - s.y) && is_free(at.x + s.x, at.y - s.y))) {
          return open(state, Cost{0, diagonal});
        }
      }
      for (const std::size_t straight : {across, along}) {
        const int steps = straight_steps(state, at, straight);
        if (steps > 0) open(state + steps * offsets_[straight], Cost{steps, diagonal});
      }
    }
  }

  [[nodiscard]] Cell cell_of(int state) const { return Cell{state % width_, state / width_}; }
  /// Known free and inside the grid.
  [[nodiscard]] bool is_free(int x, int y) const {
    return x >= 0 && y >= 0 && x < width_ && y < height_ && cells_[y * width_ + x] == CellState::Free;
  }

  const CellState* cells_;
  const std::int16_t* distances_;
  int width_;
  int height_;
  Cell goal_;
  int goal_index_;
  std::array<int, kHeadings> offsets_{};
  const OctileSearch& search_;
};

}  // namespace
}  // namespace jps_plus_detail

std::unique_ptr<Planner> JpsPlusPlanner::clone() const { return std::make_unique<JpsPlusPlanner>(params_); }

const JpsPlusPlanner::JumpTable& JpsPlusPlanner::refresh(const KnownMap& known, bool allow_corner_cutting) {
  JumpTable& table = tables_[allow_corner_cutting ? 1 : 0];
  if (table.instance_id == known.instance_id() && table.revision == known.revision()) return table;
  const auto started = std::chrono::steady_clock::now();
  if (allow_corner_cutting) {
    jps_plus_detail::TableBuilder<true>(known, padded_free_, table.distances).build();
  } else {
    jps_plus_detail::TableBuilder<false>(known, padded_free_, table.distances).build();
  }
  table.instance_id = known.instance_id();
  table.revision = known.revision();
  ++table_builds_;
  table_build_time_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return table;
}

SearchResult JpsPlusPlanner::search(const KnownMap& known, const PlanRequest& request,
                                    const StopCondition& stop) {
  const std::int16_t* distances = refresh(known, request.allow_corner_cutting).distances.data();
  // Start == goal settles the start as the goal (a one-cell path).
  if (request.allow_corner_cutting) {
    return jump_points::search_jumps(
        search_, jps_plus_detail::JumpTableEnvironment<true>(known, distances, request.goal, search_), known,
        request, stop);
  }
  return jump_points::search_jumps(
      search_, jps_plus_detail::JumpTableEnvironment<false>(known, distances, request.goal, search_), known,
      request, stop);
}

}  // namespace planners
}  // namespace fsweep
