#include "sim/trajectory_image.hpp"

#include <stb/stb_easy_font.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/config_error.hpp"
#include "core/files.hpp"
#include "core/readable_number.hpp"
#include "world/png_image.hpp"

namespace fsweep {
inline namespace sim {
namespace {

using Rgb = std::array<std::uint8_t, 3>;

constexpr Rgb kWhite{255, 255, 255};
constexpr Rgb kBlack{0, 0, 0};
constexpr Rgb kText{30, 30, 30};
constexpr Rgb kDock{0, 150, 0};
constexpr Rgb kRecharge{0, 200, 0};
constexpr Rgb kFrontier{230, 0, 230};
constexpr Rgb kUnknownFree{200, 200, 200};
constexpr Rgb kUnknownWall{120, 120, 120};

/// The narrowest picture: the legend needs about this many pixels at text size 1.
constexpr int kMinWidth = 400;
/// stb_easy_font's line height at text size 1 (its glyphs are 7 pixels tall with descenders).
constexpr int kLineHeight = 10;

/// Where everything goes: the title band, the map, the legend band (pixels).
struct Layout {
  int scale = 1;  ///< pixels per cell
  int text = 1;   ///< text size: stb_easy_font's pixels times this
  int width = 0;  ///< the picture
  int height = 0;
  int map_x = 0;  ///< the map's top-left corner
  int map_y = 0;
  int map_w = 0;
  int map_h = 0;
  int legend_y = 0;  ///< the legend band's top
};

Layout layout_of(const WorldMap& map, int scale) {
  Layout l;
  l.scale = scale;
  l.map_w = map.width() * scale;
  l.map_h = map.height() * scale;
  l.width = std::max(l.map_w, kMinWidth);
  l.text = std::clamp(l.width / 400, 1, 4);
  const int line = kLineHeight * l.text;
  l.map_x = (l.width - l.map_w) / 2;
  l.map_y = 3 * line + line / 2;  // three title lines and a gap
  l.legend_y = l.map_y + l.map_h + line / 2;
  l.height = l.legend_y + 2 * line + line / 2;  // legend and scale bar on two lines
  return l;
}

/// The image limits of check_trajectory_image(), computed in 64 bits.
struct Size {
  std::int64_t w = 0, h = 0;
};

Size picture_size(const WorldMap& map, std::int64_t scale) {
  const std::int64_t map_w = scale * map.width(), map_h = scale * map.height();
  const std::int64_t width = std::max<std::int64_t>(map_w, kMinWidth);
  const std::int64_t line = kLineHeight * std::clamp<std::int64_t>(width / 400, 1, 4);
  return {width, map_h + 6 * line + line / 2};  // as layout_of()
}

class Canvas {
 public:
  Canvas(int w, int h)
      : w_(w), h_(h), px_(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3, 255) {}

  void rect(int x0, int y0, int x1, int y1, Rgb rgb) {
    for (int y = std::max(y0, 0); y < std::min(y1, h_); ++y) {
      for (int x = std::max(x0, 0); x < std::min(x1, w_); ++x) put(x, y, rgb);
    }
  }
  /// A filled disc of radius `r` around (cx, cy) with a `ring`-pixel outline.
  void disc(double cx, double cy, double r, Rgb fill, Rgb outline, int ring) {
    const int x0 = static_cast<int>(std::floor(cx - r)), x1 = static_cast<int>(std::ceil(cx + r));
    const int y0 = static_cast<int>(std::floor(cy - r)), y1 = static_cast<int>(std::ceil(cy + r));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
        if (d <= r) put(x, y, d > r - ring ? outline : fill);
      }
    }
  }
  /// A line from (ax, ay) to (bx, by), `thick` pixels wide.
  void line(double ax, double ay, double bx, double by, Rgb rgb, int thick) {
    const int n = std::max(1, static_cast<int>(std::max(std::abs(bx - ax), std::abs(by - ay))));
    for (int i = 0; i <= n; ++i) {
      const double t = static_cast<double>(i) / n;
      const int cx = static_cast<int>(ax + t * (bx - ax));
      const int cy = static_cast<int>(ay + t * (by - ay));
      for (int dy = -thick / 2; dy <= thick / 2; ++dy) {
        for (int dx = -thick / 2; dx <= thick / 2; ++dx) put(cx + dx, cy + dy, rgb);
      }
    }
  }
  /// ASCII `text` (other bytes as '?') at (x, y), stb_easy_font's glyphs scaled by `size`;
  /// returns the text's width in pixels.
  int text(int x, int y, std::string text, int size, Rgb rgb) {
    for (char& c : text) c = c >= 32 && c < 127 ? c : '?';
    std::vector<char> buffer(text.size() * 300 + 64);
    const int quads =
        stb_easy_font_print(0, 0, text.data(), nullptr, buffer.data(), static_cast<int>(buffer.size()));
    struct Vertex {
      float x, y, z;
      unsigned char rgba[4];
    };
    const auto* v = reinterpret_cast<const Vertex*>(buffer.data());
    for (int q = 0; q < quads; ++q) {
      const Vertex* a = v + static_cast<std::ptrdiff_t>(4) * q;
      const auto px = [&](float f) { return static_cast<int>(std::lround(f * static_cast<float>(size))); };
      rect(x + px(a[0].x), y + px(a[0].y), x + px(a[2].x), y + px(a[2].y), rgb);
    }
    return stb_easy_font_width(text.data()) * size;
  }
  /// The canvas as PNG file bytes.
  [[nodiscard]] std::string png() const { return encode_png(w_, h_, px_); }

 private:
  void put(int x, int y, Rgb rgb) {
    if (x < 0 || y < 0 || x >= w_ || y >= h_) return;
    auto* p =
        &px_[(static_cast<std::size_t>(y) * static_cast<std::size_t>(w_) + static_cast<std::size_t>(x)) * 3];
    p[0] = rgb[0];
    p[1] = rgb[1];
    p[2] = rgb[2];
  }
  int w_, h_;
  std::vector<std::uint8_t> px_;
};

Rgb time_colour(double t) {
  // Blue -> red through purple: early legs blue, late legs red.
  return Rgb{static_cast<std::uint8_t>(30 + 225 * t), static_cast<std::uint8_t>(60 * (1 - t)),
             static_cast<std::uint8_t>(255 * (1 - t))};
}

/// The width in pixels of `text` at text size `size`.
int text_width(std::string text, int size) { return stb_easy_font_width(text.data()) * size; }

/// `text` cut to `pixels` wide at text size `size` (an ellipsis "..." marks the cut).
std::string fit(std::string text, int pixels, int size) {
  if (text_width(text, size) <= pixels) return text;
  while (!text.empty() && text_width(text + "...", size) > pixels) text.pop_back();
  return text + "...";
}

/// A scale bar length: 1, 2 or 5 x 10^k metres, the longest at most `max_m`.
double round_length_m(double max_m) {
  double best = 0.0;
  for (double decade = 1e-3; decade <= 1e7; decade *= 10) {
    for (const double f : {1.0, 2.0, 5.0}) {
      if (f * decade <= max_m) best = f * decade;
    }
  }
  return best;
}

/// The dock marker's radius: a cell and a half, and at least 1/120 of the picture's longer side,
/// so it shows at any map size.
double dock_radius(const Layout& l) { return std::max(1.5 * l.scale, std::max(l.width, l.height) / 120.0); }

void draw_map(Canvas& canvas, const Layout& l, const WorldMap& map, const RunResult& result) {
  const KnownMap& known = result.final_known;
  const auto cell = [&](Cell c, Rgb rgb) {
    canvas.rect(l.map_x + c.x * l.scale, l.map_y + c.y * l.scale, l.map_x + (c.x + 1) * l.scale,
                l.map_y + (c.y + 1) * l.scale, rgb);
  };
  for (int i = 0; i < map.occupied.size(); ++i) {
    const bool occ = map.occupied[i] != 0;
    const bool seen = known.size() == map.occupied.size() && known.state(i) != CellState::Unknown;
    cell(map.occupied.cell(i), occ ? (seen ? kBlack : kUnknownWall) : (seen ? kWhite : kUnknownFree));
  }
  for (const int i : result.final_frontiers) cell(map.occupied.cell(i), kFrontier);
  const auto centre = [&](Cell c) {
    return std::pair{l.map_x + (c.x + 0.5) * l.scale, l.map_y + (c.y + 0.5) * l.scale};
  };
  const auto& traj = result.trajectory;
  const int thick = std::max(1, l.scale / 3);
  for (std::size_t i = 1; i < traj.size(); ++i) {
    const auto [ax, ay] = centre(traj[i - 1]);
    const auto [bx, by] = centre(traj[i]);
    canvas.line(ax, ay, bx, by, time_colour(static_cast<double>(i) / static_cast<double>(traj.size())),
                thick);
  }
  const double r = dock_radius(l);
  for (const int s : result.recharge_steps) {
    const auto [x, y] = centre(traj[static_cast<std::size_t>(s)]);
    canvas.disc(x, y, 0.6 * r, kRecharge, kBlack, 1);
  }
  const auto [dx, dy] = centre(result.dock);
  canvas.disc(dx, dy, r, kDock, kWhite, std::max(1, static_cast<int>(r / 4)));
}

void draw_title(Canvas& canvas, const Layout& l, const RunResult& result, const TrajectoryTitle& title) {
  const int size = l.text, pad = 4 * size, line = kLineHeight * size;
  const RunMetrics& m = result.metrics;
  const std::string outcome = std::string(to_string(result.end)) + ": " + readable_number(m.distance_m) +
                              " m, coverage " + readable_number(100.0 * m.coverage, 3) + "% at " +
                              readable_number(m.distance_to_final_coverage_m) + " m, " +
                              std::to_string(m.recharges) + " recharges";
  int y = line / 4;
  for (const std::string& text :
       {title.map.empty() ? std::string() : "map " + title.map, title.strategy, outcome}) {
    canvas.text(pad, y, fit(text, l.width - 2 * pad, size), size, kText);
    y += line;
  }
}

void draw_legend(Canvas& canvas, const Layout& l, const WorldMap& map) {
  const int size = l.text, pad = 4 * size, line = kLineHeight * size, box = 6 * size;
  int x = pad;
  int y = l.legend_y;
  // 1. The path's colours, then the marks.
  for (int i = 0; i < 12 * size; ++i)
    canvas.rect(x + i, y, x + i + 1, y + box, time_colour(i / (12.0 * size)));
  x += 12 * size + 3 * size;
  x += canvas.text(x, y, "path: start -> end", size, kText) + pad * 3;
  const double r = box / 2.0 + size;
  canvas.disc(x + r, y + box / 2.0, r, kDock, kWhite, std::max(1, size / 2));
  x += static_cast<int>(2 * r) + 2 * size;
  x += canvas.text(x, y, "dock", size, kText) + pad * 3;
  canvas.disc(x + box / 2.0, y + box / 2.0, box / 2.0, kRecharge, kBlack, 1);
  x += box + 2 * size;
  x += canvas.text(x, y, "recharge", size, kText) + pad * 3;
  canvas.rect(x, y, x + box, y + box, kFrontier);
  x += box + 2 * size;
  canvas.text(x, y, "frontier left", size, kText);
  // 2. Explored and unexplored, and the scale bar.
  x = pad;
  y += line;
  for (const auto& [rgb, label] :
       {std::pair{kWhite, "free"}, std::pair{kBlack, "wall"}, std::pair{kUnknownFree, "unexplored free"},
        std::pair{kUnknownWall, "unexplored wall"}}) {
    canvas.rect(x, y, x + box, y + box, kBlack);
    canvas.rect(x + 1, y + 1, x + box - 1, y + box - 1, rgb);
    x += box + 2 * size;
    x += canvas.text(x, y, label, size, kText) + pad * 3;
  }
  const double metres_per_pixel = map.resolution_m / l.scale;
  const double length_m =
      round_length_m(std::min(0.25 * l.map_w, l.width - x - 20.0 * size) * metres_per_pixel);
  if (length_m <= 0.0) return;
  const int bar = static_cast<int>(std::lround(length_m / metres_per_pixel));
  const std::string label = readable_number(length_m) + " m";
  const int bx = l.width - pad - bar - text_width(label, size) - 2 * size;
  canvas.rect(bx, y + box / 2 - size / 2, bx + bar, y + box / 2 + (size + 1) / 2, kBlack);
  canvas.rect(bx, y, bx + size, y + box, kBlack);
  canvas.rect(bx + bar - size, y, bx + bar, y + box, kBlack);
  canvas.text(bx + bar + 2 * size, y, label, size, kText);
}

}  // namespace

std::string trajectory_strategy_text(const RunSpec& spec, const std::vector<std::string>& weight_names,
                                     const std::vector<double>& weights) {
  std::string text = spec.strategy.name;
  const nlohmann::json params = recorded_strategy_params(spec);
  if (!params.is_object()) return text;
  for (const auto& [key, value] : params.items()) {
    const auto w = std::find(weight_names.begin(), weight_names.end(), key);
    if (w != weight_names.end() && static_cast<std::size_t>(w - weight_names.begin()) < weights.size()) {
      text +=
          " " + key + "=" + readable_number(weights[static_cast<std::size_t>(w - weight_names.begin())], 6);
    } else if (value.is_number()) {
      text += " " + key + "=" + readable_number(value.get<double>(), 6);
    } else if (value.is_string()) {
      text += " " + key + "=" + value.get<std::string>();
    }
  }
  return text;
}

TrajectoryTitle trajectory_title(const RunSpec& spec, const std::string& map) {
  return TrajectoryTitle{map.empty() && spec.map ? spec.map->source : map, trajectory_strategy_text(spec)};
}

int trajectory_scale(const WorldMap& map, int scale) {
  return scale > 0 ? scale : std::clamp(800 / std::max({map.width(), map.height(), 1}), 1, 16);
}

void check_trajectory_image(const WorldMap& map, int scale, const std::string& option) {
  if (scale < 0) {
    throw ConfigError(option, "must be >= 0 pixels per cell (0: automatic), got " + std::to_string(scale));
  }
  const std::int64_t s = trajectory_scale(map, scale);
  const auto [w, h] = picture_size(map, s);
  if (w > kMaxTrajectoryImageSide || h > kMaxTrajectoryImageSide || w * h > kMaxTrajectoryImagePixels) {
    throw ConfigError(option, std::to_string(s) + " pixels per cell" + (scale == 0 ? " (automatic)" : "") +
                                  " on the " + std::to_string(map.width()) + "x" +
                                  std::to_string(map.height()) + " map makes a " + std::to_string(w) + "x" +
                                  std::to_string(h) + " image (" + std::to_string(w * h) +
                                  " pixels, with the title and the legend); allowed: at most " +
                                  std::to_string(kMaxTrajectoryImageSide) + " pixels per side and " +
                                  std::to_string(kMaxTrajectoryImagePixels) + " pixels in all");
  }
}

std::string trajectory_png(const WorldMap& map, const RunResult& result, int scale,
                           const TrajectoryTitle& title) {
  check_trajectory_image(map, scale, "scale");
  const Layout l = layout_of(map, trajectory_scale(map, scale));
  Canvas canvas(l.width, l.height);
  draw_title(canvas, l, result, title);
  draw_map(canvas, l, map, result);
  draw_legend(canvas, l, map);
  return canvas.png();
}

void write_trajectory_png(const std::string& path, const WorldMap& map, const RunResult& result, int scale,
                          const TrajectoryTitle& title) {
  write_file_atomically(path, trajectory_png(map, result, scale, title));
}

}  // namespace sim
}  // namespace fsweep
