/// @file building_generators.cpp
/// The indoor generators: `rooms` (recursive division) and `office` (corridors and rooms).
#include <algorithm>
#include <tuple>
#include <vector>

#include "world/generator_canvas.hpp"

namespace fsweep {
inline namespace world {
namespace generator_detail {

/// Rooms by recursive division. A candidate wall position is rejected when a cell just
/// beyond either end of the new wall is free: that cell is a door in the enclosing wall.
Occupancy make_rooms(const GeneratorParams& p, Rng& rng) {
  Occupancy g(p.width, p.height, kFree);
  frame(g, p.wall);
  const int t = p.wall;
  const int m = p.min_room;
  const auto is_free = [&g](int x, int y) { return g.in_bounds(Cell{x, y}) && g.at(Cell{x, y}) == kFree; };
  // Positions where a wall across `r` may start; vertical: columns, horizontal: rows.
  const auto candidates = [&](const Rect& r, bool vertical) {
    std::vector<int> out;
    const int lo = (vertical ? r.x0 : r.y0) + m;
    const int hi = (vertical ? r.x1 : r.y1) - m - t;
    for (int s = lo; s <= hi; ++s) {
      bool touches_door = false;
      for (int k = s; k < s + t && !touches_door; ++k) {
        touches_door = vertical ? (is_free(k, r.y0 - 1) || is_free(k, r.y1))
                                : (is_free(r.x0 - 1, k) || is_free(r.x1, k));
      }
      if (!touches_door) out.push_back(s);
    }
    return out;
  };
  std::vector<Rect> stack{Rect{t, t, p.width - t, p.height - t}};
  while (!stack.empty()) {
    const Rect r = stack.back();
    stack.pop_back();
    const int w = r.x1 - r.x0;
    const int h = r.y1 - r.y0;
    bool vertical = w > h || (w == h && uniform_below(rng, 2) == 0);
    std::vector<int> options = candidates(r, vertical);
    if (options.empty()) {
      vertical = !vertical;
      options = candidates(r, vertical);
    }
    if (options.empty()) continue;  // a leaf room
    const int s = options[uniform_below(rng, options.size())];
    if (vertical) {
      fill_rect(g, Rect{s, r.y0, s + t, r.y1}, kWall);
      const int d = uniform_int(rng, r.y0, r.y1 - p.door);
      fill_rect(g, Rect{s, d, s + t, d + p.door}, kFree);
      stack.push_back(Rect{s + t, r.y0, r.x1, r.y1});
      stack.push_back(Rect{r.x0, r.y0, s, r.y1});
    } else {
      fill_rect(g, Rect{r.x0, s, r.x1, s + t}, kWall);
      const int d = uniform_int(rng, r.x0, r.x1 - p.door);
      fill_rect(g, Rect{d, s, d + p.door, s + t}, kFree);
      stack.push_back(Rect{r.x0, s + t, r.x1, r.y1});
      stack.push_back(Rect{r.x0, r.y0, r.x1, s});
    }
  }
  return g;
}

/// Office: units of [rooms, wall, corridor, wall, rooms] separated by walls, plus a spine.
Occupancy make_office(const GeneratorParams& p, Rng& rng) {
  Occupancy g(p.width, p.height, kWall);
  const int t = p.wall;
  const int m = p.min_room;
  const int c = p.corridor;
  const int inner_h = p.height - 2 * t;
  const int units = (p.height - t) / (2 * m + 3 * t + c);
  const int bands = 2 * units;
  const int leftover = inner_h - (units * (2 * m + 2 * t + c) + (units - 1) * t);
  const int spine_x = uniform_int(rng, 2 * t + m, p.width - 2 * t - m - c);
  // Rooms of one band row range [y0, y1) over columns [a, b), doors on row range [door_y0, +t).
  const auto rooms = [&](int a, int b, int y0, int y1, int door_y0) {
    int x = a;
    while (x < b) {
      const int remaining = b - x;
      int room_w = remaining;
      if (remaining >= 2 * m + t) {
        room_w = std::min(uniform_int(rng, m, 2 * m), remaining - m - t);
      }
      fill_rect(g, Rect{x, y0, x + room_w, y1}, kFree);
      const int d = uniform_int(rng, x, x + room_w - p.door);
      fill_rect(g, Rect{d, door_y0, d + p.door, door_y0 + t}, kFree);
      x += room_w + t;
    }
  };
  int y = t;
  int first_corridor = 0;
  int last_corridor_end = 0;
  for (int u = 0; u < units; ++u) {
    const auto depth = [&](int band) { return m + leftover / bands + (band < leftover % bands ? 1 : 0); };
    const int top = depth(2 * u);
    const int bottom = depth(2 * u + 1);
    const int corridor_y = y + top + t;
    const int bottom_y = corridor_y + c + t;
    if (u == 0) first_corridor = corridor_y;
    last_corridor_end = corridor_y + c;
    fill_rect(g, Rect{t, corridor_y, p.width - t, corridor_y + c}, kFree);
    // The spine crosses every band between the first and the last corridor.
    for (const auto& [y0, y1, door_y0, crossed] :
         {std::tuple{y, y + top, y + top, u > 0},
          std::tuple{bottom_y, bottom_y + bottom, corridor_y + c, u + 1 < units}}) {
      if (crossed) {
        rooms(t, spine_x - t, y0, y1, door_y0);
        rooms(spine_x + c + t, p.width - t, y0, y1, door_y0);
      } else {
        rooms(t, p.width - t, y0, y1, door_y0);
      }
    }
    y = bottom_y + bottom + t;
  }
  if (units > 1) fill_rect(g, Rect{spine_x, first_corridor, spine_x + c, last_corridor_end}, kFree);
  return g;
}

}  // namespace generator_detail
}  // namespace world
}  // namespace fsweep
