#include "world/map_generators.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

#include "core/config_error.hpp"
#include "core/json_excerpt.hpp"
#include "core/random.hpp"
#include "world/generator_canvas.hpp"
#include "world/loader_support.hpp"

namespace fsweep {
inline namespace world {
namespace {

using generator_detail::frame;
using generator_detail::kFree;
using generator_detail::kWall;
using generator_detail::Occupancy;
using loader_detail::number_text;

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
Occupancy make_free(const GeneratorParams& p, Rng& /*rng*/) {
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
    for (const auto& [key, share] : {std::pair{"parks", p.park_share}, std::pair{"alleys", p.alley_share}}) {
      if (!(share >= 0.0 && share <= 1.0)) {
        throw ConfigError(where,
                          std::string(key) + " = " + number_text(share) + " is out of range; allowed: 0..1");
      }
    }
    if (p.park_share + p.alley_share > 1.0) {
      throw ConfigError(where, "parks + alleys = " + number_text(p.park_share + p.alley_share) +
                                   " is out of range; allowed: at most 1 (they are shares of the blocks)");
    }
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

/// The generator kinds, in documentation order: name, doc, the keys it reads besides the common
/// w, h, res, seed, start, and its maker.
struct KindEntry {
  const char* name;
  const char* doc;
  std::vector<const char*> keys;
  Occupancy (*make)(const GeneratorParams&, Rng&);
};

const std::vector<KindEntry>& kind_table() {
  static const std::vector<KindEntry> kKinds{
      {"free", "no obstacles, an optional occupied frame", {"border", "wall"}, &make_free},
      {"random",
       "every cell occupied with probability p (no connectivity guarantee)",
       {"border", "wall", "p"},
       &make_random},
      {"rooms",
       "recursive division into rooms joined by doors",
       {"door", "min_room", "wall"},
       &generator_detail::make_rooms},
      {"office",
       "corridors with bands of rooms, one door per room",
       {"door", "min_room", "wall", "corridor"},
       &generator_detail::make_office},
      {"manhattan",
       "a street grid of square blocks (parks, buildings with alleys)",
       {"block", "street", "parks", "alleys"},
       &generator_detail::make_manhattan},
      {"oldtown",
       "narrow winding lanes joining a few open squares",
       {"squares", "lane"},
       &generator_detail::make_oldtown},
  };
  return kKinds;
}

const KindEntry& kind_entry(const std::string& kind, const std::string& where) {
  for (const KindEntry& k : kind_table()) {
    if (kind == k.name) return k;
  }
  throw ConfigError(where,
                    "unknown generator kind '" + kind + "'; allowed: " + join_names(generator_kinds()));
}

/// One declared generator key (map-spec name, its member, range and doc).
void declare_key(ParamDecl<GeneratorParams>& d, const std::string& key) {
  using P = GeneratorParams;
  const auto integer = [&](int P::*member, double lo, double hi, const char* doc) {
    d.integer(key, member, doc).range(lo, hi).unit("cells");
  };
  if (key == "w") return integer(&P::width, 1, 65536, "map width");
  if (key == "h") return integer(&P::height, 1, 65536, "map height");
  if (key == "door") return integer(&P::door, 1, 100000, "door width (at most min_room)");
  if (key == "min_room") return integer(&P::min_room, 1, 100000, "rooms are not split below this size");
  if (key == "wall") return integer(&P::wall, 1, 100000, "wall (and frame) thickness");
  if (key == "block") return integer(&P::block, 1, 100000, "building block edge");
  if (key == "street") return integer(&P::street, 1, 100000, "street width");
  if (key == "corridor") return integer(&P::corridor, 1, 100000, "corridor width");
  if (key == "squares") return integer(&P::squares, 0, 1000, "number of open squares");
  if (key == "lane") return integer(&P::lane, 1, 100000, "lane width");
  if (key == "res") {
    d.number("res", &P::resolution_m, "cell size").above(0).unit("m");
    return;
  }
  if (key == "p") {
    d.number("p", &P::obstacle_probability, "probability that a cell is occupied").range(0, 1);
    return;
  }
  if (key == "parks") {
    d.number("parks", &P::park_share, "share of blocks that are parks (free)").range(0, 1);
    return;
  }
  if (key == "alleys") {
    d.number("alleys", &P::alley_share, "share of blocks that are buildings cut by an alley").range(0, 1);
    return;
  }
  ParamSpec spec;
  spec.name = key;
  spec.type = ParamType::Custom;
  if (key == "seed") {
    spec.doc = "generator seed (stream \"map\")";
    spec.allowed_text = "an integer >= 0";
    spec.custom_check = [](const nlohmann::json& v) -> std::vector<std::string> {
      if (v.is_number_unsigned() || (v.is_number_integer() && v.get<std::int64_t>() >= 0)) return {};
      return {"'seed' must be a non-negative integer, got " + json_excerpt(v)};
    };
    d.custom(
        std::move(spec), [](P& p, const nlohmann::json& v) { p.seed = v.get<std::uint64_t>(); },
        [](const P& p) { return nlohmann::json(p.seed); });
  } else if (key == "border") {
    spec.doc = "an occupied frame `wall` cells thick around the map";
    spec.allowed_text = "true, false, 1 or 0";
    spec.custom_check = [](const nlohmann::json& v) -> std::vector<std::string> {
      if (v.is_boolean() || (v.is_number_integer() && (v.get<long long>() == 0 || v.get<long long>() == 1))) {
        return {};
      }
      return {"'border' must be true, false, 1 or 0, got " + json_excerpt(v)};
    };
    d.custom(
        std::move(spec),
        [](P& p, const nlohmann::json& v) {
          p.border = v.is_boolean() ? v.get<bool>() : v.get<long long>() == 1;
        },
        [](const P& p) { return nlohmann::json(p.border); });
  } else if (key == "start") {
    spec.nullable = true;
    spec.doc = "start cell (default: the free cell nearest the centre in the largest free component)";
    spec.allowed_text = "[x, y] or \"x;y\", non-negative integers";
    spec.custom_check = [](const nlohmann::json& v) -> std::vector<std::string> {
      if (parse_cell_pair(v)) return {};
      return {"start must be two non-negative integer cell coordinates, [x, y] or \"x;y\", got " +
              json_excerpt(v)};
    };
    d.custom(
        std::move(spec),
        [](P& p, const nlohmann::json& v) {
          const auto c = parse_cell_pair(v);
          p.start_x = c ? c->x : -1;
          p.start_y = c ? c->y : -1;
        },
        [](const P& p) {
          return p.start_x < 0 ? nlohmann::json() : nlohmann::json{p.start_x, p.start_y};
        });
  } else {
    throw std::logic_error("generator key '" + key + "' is not declared");
  }
}

GeneratorRegistry make_generator_registry() {
  GeneratorRegistry r("generator");
  for (const KindEntry& k : kind_table()) {
    ParamDecl<GeneratorParams> d;
    for (const char* key : {"w", "h", "res", "seed", "start"}) declare_key(d, key);
    for (const char* key : k.keys) declare_key(d, key);
    const std::string name = k.name;
    r.add<GeneratorParams>(name, k.doc, d, [name](const GeneratorParams& params) {
      GeneratorParams p = params;
      p.kind = name;
      return generate_map(p);
    });
  }
  return r;
}

}  // namespace

std::optional<Cell> parse_cell_pair(const nlohmann::json& v) {
  double x = -1.0;
  double y = -1.0;
  if (v.is_array() && v.size() == 2 && v[0].is_number() && v[1].is_number()) {
    x = v[0].get<double>();
    y = v[1].get<double>();
  } else if (v.is_string()) {
    const std::string s = v.get<std::string>();
    const std::size_t cut = s.find(';');
    if (cut == std::string::npos) return std::nullopt;
    const char* mid = s.data() + cut;
    const char* end = s.data() + s.size();
    const auto rx = std::from_chars(s.data(), mid, x);
    const auto ry = std::from_chars(mid + 1, end, y);
    if (rx.ec != std::errc() || rx.ptr != mid || ry.ec != std::errc() || ry.ptr != end) return std::nullopt;
  } else {
    return std::nullopt;
  }
  if (x != std::floor(x) || y != std::floor(y) || x < 0 || y < 0 || x > 1e9 || y > 1e9) return std::nullopt;
  return Cell{static_cast<int>(x), static_cast<int>(y)};
}

const GeneratorRegistry& generator_registry() {
  static const GeneratorRegistry kRegistry = make_generator_registry();
  return kRegistry;
}

std::vector<std::string> generator_kinds() {
  std::vector<std::string> names;
  for (const KindEntry& k : kind_table()) names.emplace_back(k.name);
  return names;
}

WorldMap generate_map(const GeneratorParams& params) {
  const std::string where = "generator '" + params.kind + "'";
  validate(params, where);
  Rng rng = make_rng(params.seed, "map");
  WorldMap map;
  map.resolution_m = params.resolution_m;
  map.source = params.kind + ":w=" + std::to_string(params.width) + ",h=" + std::to_string(params.height) +
               ",seed=" + std::to_string(params.seed);
  map.occupied = kind_entry(params.kind, where).make(params, rng);
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
