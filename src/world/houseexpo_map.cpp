/// @file houseexpo_map.cpp
/// HouseExpo floor plans (map_loaders.hpp, load_houseexpo()).

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/config_error.hpp"
#include "core/json_text.hpp"
#include "world/loader_support.hpp"
#include "world/map_loaders.hpp"
#include "world/polygon_fill.hpp"

namespace fsweep {
inline namespace world {
namespace {

using loader_detail::number_text;
using nlohmann::json;

/// Deeper JSON than this is refused while parsing (a plan nests 4 levels).
constexpr int kMaxPlanDepth = 16;
/// Largest grid a plan may make, as for bitmaps.
constexpr long long kMaxPlanCells = 100'000'000;
/// Largest cell coordinate a vertex may scale to before the grid size is checked.
constexpr double kMaxCellCoordinate = 1e9;

json read_plan_json(const std::string& path) {
  const std::string text = loader_detail::read_whole_file(path, "cannot open the file for reading");
  const json::parser_callback_t depth_guard = [&path](int depth, json::parse_event_t /*event*/,
                                                      json& /*parsed*/) {
    if (depth > kMaxPlanDepth) {
      throw ConfigError(path, "JSON nested deeper than " + std::to_string(kMaxPlanDepth) +
                                  " levels; a HouseExpo plan nests 4");
    }
    return true;
  };
  try {
    return json::parse(text, depth_guard);
  } catch (const json::parse_error& e) {
    // e.byte: 1-based position of the offending character; the reason follows nlohmann's
    // "... column C: ".
    std::string detail = e.what();
    if (const std::size_t colon = detail.find(": ", detail.find("column")); colon != std::string::npos) {
      detail = detail.substr(colon + 2);
    }
    if (detail.size() > 200) detail = detail.substr(0, 200) + "...";
    throw ConfigError(text_position(path, text, e.byte == 0 ? 0 : e.byte - 1),
                      "not a valid JSON file: " + detail);
  } catch (const json::out_of_range&) {
    // 406: a number beyond a double; nlohmann names neither the file nor the place.
    const auto [offset, number] = first_overflowing_number(text);
    throw ConfigError(text_position(path, text, offset),
                      "number " + (number.size() > 40 ? number.substr(0, 40) + "..." : number) +
                          " is out of range; allowed: numbers of magnitude below 1.8e308 (a double)");
  }
}

/// Cells per metre: 1 / resolution, snapped to an integer within 1e-9 (PseudoSLAM's meter2pixel
/// is an integer, and 1 / 0.04 must be exactly 25 for its truncations to come out the same).
double cells_per_metre(double resolution_m) {
  const double k = 1.0 / resolution_m;
  const double nearest = std::round(k);
  return std::abs(k - nearest) <= 1e-9 * std::max(1.0, k) ? nearest : k;
}

}  // namespace

WorldMap load_houseexpo(const std::string& path, double resolution_m) {
  loader_detail::require_positive_resolution(resolution_m, path);
  const json plan = read_plan_json(path);
  if (!plan.is_object() || !plan.contains("verts")) {
    throw ConfigError(path,
                      "a HouseExpo plan is a JSON object with the key 'verts' (the free-space contour in "
                      "metres, [[x, y], ...])");
  }
  const json& verts = plan.at("verts");
  if (!verts.is_array() || verts.size() < 3) {
    throw ConfigError(path + ": /verts", "expected a list of at least 3 vertices [x, y] in metres");
  }
  const double scale = cells_per_metre(resolution_m);
  std::vector<Cell> cells;
  cells.reserve(verts.size());
  long long x_min = std::numeric_limits<long long>::max();
  long long y_min = x_min;
  long long x_max = std::numeric_limits<long long>::min();
  long long y_max = x_max;
  for (std::size_t i = 0; i < verts.size(); ++i) {
    const json& v = verts[i];
    const std::string where = path + ": /verts/" + std::to_string(i);
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number()) {
      throw ConfigError(where, "expected a vertex [x, y] of two numbers (metres)");
    }
    const double px = std::trunc(v[0].get<double>() * scale);
    const double py = std::trunc(v[1].get<double>() * scale);
    if (!(std::abs(px) <= kMaxCellCoordinate) || !(std::abs(py) <= kMaxCellCoordinate)) {
      throw ConfigError(where, "vertex (" + number_text(v[0].get<double>()) + ", " +
                                   number_text(v[1].get<double>()) + ") m is out of range at " +
                                   number_text(resolution_m) +
                                   " m per cell; allowed: finite, within 1e9 cells of the origin");
    }
    const Cell c{static_cast<int>(px), static_cast<int>(py)};
    x_min = std::min<long long>(x_min, c.x);
    y_min = std::min<long long>(y_min, c.y);
    x_max = std::max<long long>(x_max, c.x);
    y_max = std::max<long long>(y_max, c.y);
    cells.push_back(c);
  }
  constexpr long long kBorder = 1;
  const long long width = x_max - x_min + 1 + 2 * kBorder;
  const long long height = y_max - y_min + 1 + 2 * kBorder;
  if (width * height > kMaxPlanCells) {
    throw ConfigError(path, "the plan is " + std::to_string(width) + "x" + std::to_string(height) +
                                " cells at " + number_text(resolution_m) +
                                " m per cell, over the limit of 10^8 cells; choose a "
                                "coarser res");
  }
  for (Cell& c : cells) {
    c.x = static_cast<int>(c.x - x_min + kBorder);
    c.y = static_cast<int>(c.y - y_min + kBorder);
  }
  WorldMap map;
  map.resolution_m = resolution_m;
  map.source = path;
  map.occupied = Grid<std::uint8_t>(static_cast<int>(width), static_cast<int>(height), 1);
  fill_polygon(map.occupied, cells, 0);
  // The start: a plan has none; the cell nearest the centre of the largest free region under the
  // default motion rule (8-connected without corner cutting, so its regions are the 4-connected
  // ones), rather than the first free cell, which lies in a corner of the outline.
  map.start = region_centre_cell(largest_free_region(map, /*allow_corner_cutting=*/false));
  if (map.start.x < 0) throw ConfigError(path, "the plan has no free cell, so there is no start cell");
  return map;
}

}  // namespace world
}  // namespace fsweep
