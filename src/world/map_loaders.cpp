#include "world/map_loaders.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <sstream>
#include <string_view>

#include "core/config_error.hpp"
#include "world/loader_support.hpp"

namespace fsweep {
inline namespace world {
namespace {

using loader_detail::at_line;
using loader_detail::require_map_size;
using loader_detail::require_positive_resolution;
using loader_detail::set_first_free_start;

std::string read_text_file(const std::string& path) {
  return loader_detail::read_whole_file(path, "cannot open the file for reading");
}

/// Lines of `text` without their '\n' or "\r\n" terminators.
std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(begin, end - begin);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
    begin = end + 1;
  }
  return lines;
}

bool is_blank(std::string_view s) {
  return std::all_of(s.begin(), s.end(), [](char c) { return c == ' ' || c == '\t' || c == '\r'; });
}

/// Whitespace-separated words of a line.
std::vector<std::string> words_of(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  std::string w;
  while (in >> w) words.push_back(w);
  return words;
}

/// Parses the whole of `s` as an integer or double; false if anything is left over.
template <typename T>
bool parse_number(std::string_view s, T& value) {
  const char* end = s.data() + s.size();
  const auto result = std::from_chars(s.data(), end, value);
  return result.ec == std::errc() && result.ptr == end;
}

}  // namespace

WorldMap load_movingai_map(const std::string& path, double resolution_m) {
  require_positive_resolution(resolution_m, path);
  const std::string text = read_text_file(path);
  const std::vector<std::string> lines = split_lines(text);
  int width = -1;
  int height = -1;
  std::size_t width_line = 0;  // 1-based lines of the header's width and height
  std::size_t height_line = 0;
  std::size_t line_no = 0;
  std::size_t header_bytes = 0;  // bytes of the header lines, with their line ends
  // 1. Header: `type octile`, `height H`, `width W` (either order), then `map`.
  bool saw_map = false;
  for (; line_no < lines.size() && !saw_map; ++line_no) {
    header_bytes = std::min(text.size(), header_bytes + lines[line_no].size() + 1);
    const std::vector<std::string> words = words_of(lines[line_no]);
    const std::string where = at_line(path, static_cast<int>(line_no) + 1);
    if (words.empty()) continue;
    if (words[0] == "map" && words.size() == 1) {
      saw_map = true;
    } else if (words[0] == "type" && words.size() == 2) {
      if (words[1] != "octile") {
        throw ConfigError(where, "map type '" + words[1] + "' is not supported; allowed: octile");
      }
    } else if ((words[0] == "height" || words[0] == "width") && words.size() == 2) {
      int value = 0;
      if (!parse_number(words[1], value) || value <= 0) {
        throw ConfigError(where, words[0] + " '" + words[1] + "' is not a positive integer");
      }
      (words[0] == "height" ? height : width) = value;
      (words[0] == "height" ? height_line : width_line) = line_no + 1;
    } else {
      throw ConfigError(where, "unexpected header line '" + lines[line_no] +
                                   "'; allowed: 'type octile', 'height H', 'width W', 'map'");
    }
  }
  if (!saw_map || width < 0 || height < 0) {
    throw ConfigError(path,
                      "incomplete MovingAI header; it needs 'type octile', 'height H', 'width W' "
                      "and a 'map' line before the rows");
  }
  // 2. The declared size, checked before allocating: at most kMaxMapCells, no more rows than the
  // file has lines left, and no more cells than it has bytes left.
  require_map_size(width, height, at_line(path, static_cast<int>(std::max(width_line, height_line))));
  const std::size_t lines_left = lines.size() - line_no;
  if (static_cast<std::size_t>(height) > lines_left) {
    throw ConfigError(at_line(path, static_cast<int>(height_line)),
                      "height " + std::to_string(height) + ": the header promises " + std::to_string(height) +
                          " rows but only " + std::to_string(lines_left) + " lines follow the 'map' line");
  }
  const std::size_t bytes_left = text.size() - header_bytes;
  if (static_cast<std::size_t>(width) * static_cast<std::size_t>(height) > bytes_left) {
    throw ConfigError(at_line(path, static_cast<int>(width_line)),
                      "width " + std::to_string(width) + " x height " + std::to_string(height) +
                          " cells do not fit in the " + std::to_string(bytes_left) +
                          " bytes that follow the 'map' line");
  }
  // 3. Exactly `height` rows of `width` characters.
  WorldMap map;
  map.occupied = Grid<std::uint8_t>(width, height, 1);
  map.resolution_m = resolution_m;
  map.source = path;
  for (int y = 0; y < height; ++y, ++line_no) {
    const std::string& row = lines[line_no];
    const std::string where = at_line(path, static_cast<int>(line_no) + 1);
    if (static_cast<int>(row.size()) != width) {
      throw ConfigError(where, "row " + std::to_string(y) + " has " + std::to_string(row.size()) +
                                   " characters; the header says width " + std::to_string(width));
    }
    for (int x = 0; x < width; ++x) {
      const char c = row[static_cast<std::size_t>(x)];
      std::uint8_t occupied = 0;
      if (c == '.' || c == 'G' || c == 'S') {
        occupied = 0;
      } else if (c == '@' || c == 'O' || c == 'T' || c == 'W') {
        occupied = 1;
      } else {
        throw ConfigError(where, "character '" + std::string(1, c) + "' at cell (" + std::to_string(x) +
                                     ", " + std::to_string(y) +
                                     ") is not allowed; allowed: . G S (free), @ O T W (occupied)");
      }
      map.occupied.at(Cell{x, y}) = occupied;
    }
  }
  // 4. Nothing but blank lines may follow.
  for (; line_no < lines.size(); ++line_no) {
    if (!is_blank(lines[line_no])) {
      throw ConfigError(at_line(path, static_cast<int>(line_no) + 1),
                        "unexpected content after the " + std::to_string(height) + " map rows");
    }
  }
  set_first_free_start(map);
  return map;
}

WorldMap parse_ascii_map(const std::string& text, double resolution_m, const std::string& source) {
  require_positive_resolution(resolution_m, source);
  std::vector<std::string> rows = split_lines(text);
  while (!rows.empty() && rows.back().empty()) rows.pop_back();
  if (rows.empty() || rows.front().empty()) {
    throw ConfigError(source, "an ASCII map needs at least one non-empty row");
  }
  const int width = static_cast<int>(rows.front().size());
  const int height = static_cast<int>(rows.size());
  WorldMap map;
  map.occupied = Grid<std::uint8_t>(width, height, 1);
  map.resolution_m = resolution_m;
  map.source = source;
  bool has_start = false;
  for (int y = 0; y < height; ++y) {
    const std::string& row = rows[static_cast<std::size_t>(y)];
    const std::string where = at_line(source, y + 1);
    if (static_cast<int>(row.size()) != width) {
      throw ConfigError(where, "row has " + std::to_string(row.size()) + " characters; all rows must have " +
                                   std::to_string(width) + " like the first");
    }
    for (int x = 0; x < width; ++x) {
      const char c = row[static_cast<std::size_t>(x)];
      if (c == '#') continue;
      if (c != '.' && c != 'S') {
        throw ConfigError(where, "character '" + std::string(1, c) + "' at cell (" + std::to_string(x) +
                                     ", " + std::to_string(y) +
                                     ") is not allowed; allowed: . (free), # (occupied), S (start)");
      }
      map.occupied.at(Cell{x, y}) = 0;
      if (c == 'S') {
        if (has_start) throw ConfigError(where, "a second start 'S'; at most one is allowed");
        has_start = true;
        map.start = Cell{x, y};
      }
    }
  }
  if (!has_start) set_first_free_start(map);
  return map;
}

WorldMap load_ascii_map(const std::string& path, double resolution_m) {
  return parse_ascii_map(read_text_file(path), resolution_m, path);
}

std::vector<ScenarioQuery> load_scenario(const std::string& path) {
  const std::vector<std::string> lines = split_lines(read_text_file(path));
  if (lines.empty() || words_of(lines.front()).size() != 2 || words_of(lines.front())[0] != "version") {
    throw ConfigError(at_line(path, 1), "a scenario file starts with 'version 1'");
  }
  std::vector<ScenarioQuery> queries;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    if (is_blank(line)) continue;
    const std::string where = at_line(path, static_cast<int>(i) + 1);
    // Fields are tab-separated (a map name may then contain spaces); fall back to whitespace.
    std::vector<std::string> fields;
    std::size_t begin = 0;
    while (true) {
      const std::size_t tab = line.find('\t', begin);
      fields.push_back(line.substr(begin, tab == std::string::npos ? std::string::npos : tab - begin));
      if (tab == std::string::npos) break;
      begin = tab + 1;
    }
    if (fields.size() != 9) fields = words_of(line);
    if (fields.size() != 9) {
      throw ConfigError(where, "expected 9 fields (bucket map W H sx sy gx gy optimal_length), got " +
                                   std::to_string(fields.size()));
    }
    static constexpr std::array<const char*, 9> kNames{"bucket",     "map",     "map width",
                                                       "map height", "start x", "start y",
                                                       "goal x",     "goal y",  "optimal_length"};
    std::array<int, 9> ints{};
    for (std::size_t f : {0U, 2U, 3U, 4U, 5U, 6U, 7U}) {
      if (!parse_number(fields[f], ints[f]) || ints[f] < 0) {
        throw ConfigError(where,
                          std::string(kNames[f]) + " '" + fields[f] + "' is not a non-negative integer");
      }
    }
    ScenarioQuery q;
    q.bucket = ints[0];
    q.map_name = fields[1];
    q.map_width = ints[2];
    q.map_height = ints[3];
    q.start = Cell{ints[4], ints[5]};
    q.goal = Cell{ints[6], ints[7]};
    if (!parse_number(fields[8], q.optimal_length) || !(q.optimal_length >= 0.0)) {
      throw ConfigError(where, "optimal_length '" + fields[8] + "' is not a non-negative number");
    }
    if (q.start.x >= q.map_width || q.start.y >= q.map_height || q.goal.x >= q.map_width ||
        q.goal.y >= q.map_height) {
      throw ConfigError(where, "start or goal lies outside the " + std::to_string(q.map_width) + "x" +
                                   std::to_string(q.map_height) + " map");
    }
    queries.push_back(std::move(q));
  }
  return queries;
}

}  // namespace world
}  // namespace fsweep
