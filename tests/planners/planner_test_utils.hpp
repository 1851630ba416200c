#pragma once
/// @file planner_test_utils.hpp
/// Tiny hand-made maps and path checks shared by the planner tests.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "core/random.hpp"
#include "planners/planner.hpp"
#include "search/octile_grid.hpp"
#include "world/known_map.hpp"
#include "world/motion.hpp"

namespace fsweep::testing {

/// A known map drawn in ASCII: `.` free, `#` occupied, `?` unknown, `S` free start, `G` free
/// goal. All rows have the same length; row 0 is y = 0.
struct AsciiKnownMap {
  KnownMap known;
  Cell start{-1, -1};
  Cell goal{-1, -1};
};

inline AsciiKnownMap known_from_ascii(std::initializer_list<std::string_view> rows,
                                      double resolution_m = 1.0) {
  AsciiKnownMap m;
  const int height = static_cast<int>(rows.size());
  const int width = height == 0 ? 0 : static_cast<int>(rows.begin()->size());
  m.known = KnownMap(width, height, resolution_m);
  int y = 0;
  for (const std::string_view row : rows) {
    EXPECT_EQ(static_cast<int>(row.size()), width) << "ragged ASCII map row " << y;
    for (int x = 0; x < width && x < static_cast<int>(row.size()); ++x) {
      const char c = row[static_cast<std::size_t>(x)];
      const int i = m.known.index(Cell{x, y});
      if (c == '#') m.known.reveal(i, true);
      if (c == '.' || c == 'S' || c == 'G') m.known.reveal(i, false);
      if (c == 'S') m.start = Cell{x, y};
      if (c == 'G') m.goal = Cell{x, y};
    }
    ++y;
  }
  return m;
}

/// A fully known random map: each cell occupied with probability `p_occupied` (seeded).
inline KnownMap random_known_map(int width, int height, double p_occupied, std::uint64_t seed,
                                 double resolution_m = 1.0) {
  KnownMap known(width, height, resolution_m);
  Rng rng = make_rng(seed, "planner_test_map");
  for (int i = 0; i < known.size(); ++i) known.reveal(i, uniform01(rng) < p_occupied);
  return known;
}

/// A uniformly drawn known-free cell (the map must have one).
inline Cell random_free_cell(const KnownMap& known, Rng& rng) {
  for (;;) {
    const int i = static_cast<int>(uniform_below(rng, static_cast<std::uint64_t>(known.size())));
    if (known.is_free(i)) return known.cell(i);
  }
}

/// Length of a cell chain in cells (1 per orthogonal step, sqrt(2) per diagonal step).
inline double chain_length_cells(const std::vector<Cell>& path) {
  double cells = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const bool diagonal = path[i].x != path[i - 1].x && path[i].y != path[i - 1].y;
    cells += diagonal ? kSqrt2 : 1.0;
  }
  return cells;
}

/// Checks a successful plan: starts at the start, ends at the goal, every cell known free,
/// consecutive cells are 8-neighbours, no corner cut unless allowed, and length_m is the
/// chain length.
inline void expect_valid_path(const KnownMap& known, const PlanRequest& request, const PlanResult& result) {
  ASSERT_EQ(result.status, PlanStatus::Success);
  ASSERT_FALSE(result.path.empty());
  EXPECT_EQ(result.path.front(), request.start);
  EXPECT_EQ(result.path.back(), request.goal);
  for (std::size_t i = 0; i < result.path.size(); ++i) {
    const Cell c = result.path[i];
    EXPECT_TRUE(known.is_free(c)) << "cell " << i << " (" << c.x << "," << c.y << ") is not known free";
    if (i == 0) continue;
    const Cell p = result.path[i - 1];
    EXPECT_TRUE(octile_step_allowed(known, p, c, request.allow_corner_cutting))
        << "step " << i << " (" << p.x << "," << p.y << ")->(" << c.x << "," << c.y
        << ") is not an allowed 8-connected move";
  }
  EXPECT_NEAR(result.length_m, chain_length_cells(result.path) * known.resolution_m(), 1e-9);
  // The motion totals are those of the cells returned, exactly, also where a planner works
  // them out from its path's runs (SearchResult::motion).
  const MotionCost cells =
      measure_path(result.path, request.start_heading, request.energy, known.resolution_m());
  EXPECT_EQ(result.length_m, cells.length_m);
  EXPECT_EQ(result.energy, cells.energy);
  EXPECT_EQ(result.stops, cells.stops);
  EXPECT_EQ(result.turns, cells.turns);
}

/// A query from `start` to `goal` with the default energy model and start heading.
inline PlanRequest request_for(Cell start, Cell goal, bool allow_corner_cutting = false) {
  PlanRequest r;
  r.start = start;
  r.goal = goal;
  r.allow_corner_cutting = allow_corner_cutting;
  return r;
}

/// A query under the `mei2006` energy preset (Mei 2006 section V-A).
inline PlanRequest mei_request(Cell start, Cell goal, int start_heading = 0) {
  PlanRequest r;
  r.start = start;
  r.goal = goal;
  r.start_heading = start_heading;
  r.energy = energy_preset("mei2006");
  return r;
}

}  // namespace fsweep::testing
