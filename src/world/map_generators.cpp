#include "world/map_generators.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <limits>
#include <sstream>
#include <vector>

#include "core/config_error.hpp"
#include "core/random.hpp"
#include "world/generator_canvas.hpp"

namespace fsweep {
inline namespace world {
namespace {

using generator_detail::frame;
using generator_detail::kFree;
using generator_detail::kWall;
using generator_detail::Occupancy;

/// A number for messages: shortest form with up to 10 significant digits (0.05, not 0.050000).
std::string number_text(double v) {
  std::ostringstream out;
  out << std::setprecision(10) << v;
  return out.str();
}

/// Throws unless lo <= value <= hi; `key` is the map-spec key of the parameter.
void require_range(const std::string& where, const char* key, long long value, long long lo, long long hi,
                   const std::string& why = "") {
  if (value < lo || value > hi) {
    throw ConfigError(where, std::string(key) + " = " + std::to_string(value) +
                                 " is out of range; allowed: " + std::to_string(lo) + ".." +
                                 std::to_string(hi) + why);
  }
}

/// Free space and random obstacles (see map_generators.hpp).
Occupancy make_free(const GeneratorParams& p) {
  Occupancy g(p.width, p.height, kFree);
  if (p.border) frame(g, p.wall);
  return g;
}

Occupancy make_random(const GeneratorParams& p, Rng& rng) {
  Occupancy g(p.width, p.height, kFree);
  for (int i = 0; i < g.size(); ++i) g[i] = uniform01(rng) < p.obstacle_probability ? kWall : kFree;
  if (p.border) frame(g, p.wall);
  return g;
}

/// Default start: the largest free component (8-connected, no corner cutting; ties by its lowest
/// index), and in it the cell nearest the centre (ties by lowest index).
Cell default_start(const WorldMap& map) {
  Grid<int> label(map.width(), map.height(), -1);
  int best_label = -1;
  int best_size = 0;
  int next_label = 0;
  std::vector<int> queue;
  for (int i = 0; i < map.occupied.size(); ++i) {
    if (!map.is_free(i) || label[i] >= 0) continue;
    // Components are labelled by flood fill; reachable_free gives the same sets.
    queue.assign(1, i);
    label[i] = next_label;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const Cell c = map.occupied.cell(queue[head]);
      for (int h = 0; h < 8; ++h) {
        const Cell d = kDirections[static_cast<std::size_t>(h)];
        const Cell nb{c.x + d.x, c.y + d.y};
        if (!map.is_free(nb) || label.at(nb) >= 0) continue;
        if ((h & 1) != 0 && (!map.is_free(Cell{nb.x, c.y}) || !map.is_free(Cell{c.x, nb.y}))) continue;
        label.at(nb) = next_label;
        queue.push_back(map.occupied.index(nb));
      }
    }
    if (static_cast<int>(queue.size()) > best_size) {
      best_size = static_cast<int>(queue.size());
      best_label = next_label;
    }
    ++next_label;
  }
  const Cell centre{map.width() / 2, map.height() / 2};
  Cell best{-1, -1};
  long long best_d2 = std::numeric_limits<long long>::max();
  for (int i = 0; i < map.occupied.size(); ++i) {
    if (label[i] != best_label || best_label < 0) continue;
    const Cell c = map.occupied.cell(i);
    const long long dx = c.x - centre.x;
    const long long dy = c.y - centre.y;
    if (dx * dx + dy * dy < best_d2) {
      best_d2 = dx * dx + dy * dy;
      best = c;
    }
  }
  return best;
}

/// Range checks of every parameter the kind reads; messages name the spec key.
void validate(const GeneratorParams& p, const std::string& where) {
  require_range(where, "w", p.width, 1, 65536);
  require_range(where, "h", p.height, 1, 65536);
  if (static_cast<long long>(p.width) * p.height > 100'000'000LL) {
    throw ConfigError(where, "w x h = " + std::to_string(static_cast<long long>(p.width) * p.height) +
                                 " cells is too large; allowed: at most 100000000");
  }
  if (!(p.resolution_m > 0.0) || !std::isfinite(p.resolution_m)) {
    throw ConfigError(where,
                      "res = " + number_text(p.resolution_m) + " is out of range; allowed: > 0 metres");
  }
  const int min_side = std::min(p.width, p.height);
  const std::string& k = p.kind;
  if (k == "free" || k == "random") {
    if (p.border)
      require_range(where, "wall", p.wall, 1, (min_side - 1) / 2, " (the frame must leave a free cell)");
    if (k == "random" && !(p.obstacle_probability >= 0.0 && p.obstacle_probability <= 1.0)) {
      throw ConfigError(where,
                        "p = " + number_text(p.obstacle_probability) + " is out of range; allowed: 0..1");
    }
  } else if (k == "rooms" || k == "office") {
    require_range(where, "wall", p.wall, 1, 1000);
    require_range(where, "min_room", p.min_room, 1, 100000);
    require_range(where, "door", p.door, 1, p.min_room, " (at most min_room)");
    int need = p.min_room + 2 * p.wall;
    if (k == "office") {
      require_range(where, "corridor", p.corridor, 1, 100000);
      need = 2 * p.min_room + p.corridor + 4 * p.wall;
    }
    require_range(where, "w", p.width, need, 65536, " (" + k + " needs room for its walls and rooms)");
    require_range(where, "h", p.height, need, 65536, " (" + k + " needs room for its walls and rooms)");
  } else if (k == "manhattan") {
    require_range(where, "block", p.block, 1, 100000);
    require_range(where, "street", p.street, 1, 100000);
    require_range(where, "w", p.width, p.block + 2 * p.street, 65536, " (at least block + 2 * street)");
    require_range(where, "h", p.height, p.block + 2 * p.street, 65536, " (at least block + 2 * street)");
  } else if (k == "oldtown") {
    require_range(where, "lane", p.lane, 1, (min_side - 2) / 3, " (w and h must be >= 3 * lane + 2)");
    require_range(where, "squares", p.squares, 0, 1000);
  } else {
    throw ConfigError(where, "unknown generator kind '" + k + "'; allowed: " + join_names(generator_kinds()));
  }
  if ((p.start_x >= 0) != (p.start_y >= 0)) {
    throw ConfigError(where, "give both start coordinates or neither");
  }
}

}  // namespace

std::vector<std::string> generator_kinds() {
  return {"free", "random", "rooms", "office", "manhattan", "oldtown"};
}

WorldMap generate_map(const GeneratorParams& params) {
  const std::string where = "generator '" + params.kind + "'";
  validate(params, where);
  Rng rng = make_rng(params.seed, "map");
  WorldMap map;
  map.resolution_m = params.resolution_m;
  map.source = params.kind + ":w=" + std::to_string(params.width) + ",h=" + std::to_string(params.height) +
               ",seed=" + std::to_string(params.seed);
  const std::string& k = params.kind;
  if (k == "free") {
    map.occupied = make_free(params);
  } else if (k == "random") {
    map.occupied = make_random(params, rng);
  } else if (k == "rooms") {
    map.occupied = generator_detail::make_rooms(params, rng);
  } else if (k == "office") {
    map.occupied = generator_detail::make_office(params, rng);
  } else if (k == "manhattan") {
    map.occupied = generator_detail::make_manhattan(params, rng);
  } else {
    map.occupied = generator_detail::make_oldtown(params, rng);
  }
  if (params.start_x >= 0) {
    const Cell s{params.start_x, params.start_y};
    const std::string cell = "start cell (" + std::to_string(s.x) + ", " + std::to_string(s.y) + ")";
    if (!map.occupied.in_bounds(s)) {
      throw ConfigError(where, cell + " is outside the " + std::to_string(map.width()) + "x" +
                                   std::to_string(map.height()) + " map");
    }
    if (!map.is_free(s)) throw ConfigError(where, cell + " is occupied; choose a free cell");
    map.start = s;
  } else {
    map.start = default_start(map);
    if (map.start.x < 0) throw ConfigError(where, "the generated map has no free cell");
  }
  return map;
}

}  // namespace world
}  // namespace fsweep
