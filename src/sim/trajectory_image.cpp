#include "sim/trajectory_image.hpp"

#include <stb/stb_image_write.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/config_error.hpp"
#include "core/files.hpp"

namespace fsweep {
inline namespace sim {
namespace {

using Rgb = std::array<std::uint8_t, 3>;

class Canvas {
 public:
  /// `w` x `h` cells of `scale` pixels (check_trajectory_image() bounds the product).
  Canvas(int w, int h, int scale)
      : w_(w * scale),
        h_(h * scale),
        scale_(scale),
        px_(static_cast<std::size_t>(w_) * static_cast<std::size_t>(h_) * 3) {}
  void cell(Cell c, Rgb rgb, int shrink = 0) {
    for (int y = c.y * scale_ + shrink; y < (c.y + 1) * scale_ - shrink; ++y) {
      for (int x = c.x * scale_ + shrink; x < (c.x + 1) * scale_ - shrink; ++x) put(x, y, rgb);
    }
  }
  /// A line between two cell centres, `thick` pixels wide.
  void line(Cell a, Cell b, Rgb rgb, int thick) {
    const double ax = (a.x + 0.5) * scale_, ay = (a.y + 0.5) * scale_;
    const double bx = (b.x + 0.5) * scale_, by = (b.y + 0.5) * scale_;
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
  /// The canvas as PNG file bytes.
  [[nodiscard]] std::string png() const {
    std::string bytes;
    auto append = [](void* context, void* data, int size) {
      static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                                 static_cast<std::size_t>(size));
    };
    if (stbi_write_png_to_func(append, &bytes, w_, h_, 3, px_.data(), w_ * 3) == 0) {
      throw std::runtime_error("stb could not encode a PNG of " + std::to_string(w_) + " x " +
                               std::to_string(h_) + " pixels");
    }
    return bytes;
  }

 private:
  void put(int x, int y, Rgb rgb) {
    if (x < 0 || y < 0 || x >= w_ || y >= h_) return;
    auto* p =
        &px_[(static_cast<std::size_t>(y) * static_cast<std::size_t>(w_) + static_cast<std::size_t>(x)) * 3];
    p[0] = rgb[0];
    p[1] = rgb[1];
    p[2] = rgb[2];
  }
  int w_, h_, scale_;
  std::vector<std::uint8_t> px_;
};

Rgb time_colour(double t) {
  // Blue -> red through purple: early legs blue, late legs red.
  return Rgb{static_cast<std::uint8_t>(30 + 225 * t), static_cast<std::uint8_t>(60 * (1 - t)),
             static_cast<std::uint8_t>(255 * (1 - t))};
}

}  // namespace

int trajectory_scale(const WorldMap& map, int scale) {
  return scale > 0 ? scale : std::clamp(800 / std::max({map.width(), map.height(), 1}), 1, 16);
}

void check_trajectory_image(const WorldMap& map, int scale, const std::string& option) {
  if (scale < 0) {
    throw ConfigError(option, "must be >= 0 pixels per cell (0: automatic), got " + std::to_string(scale));
  }
  const std::int64_t s = trajectory_scale(map, scale);
  const std::int64_t w = s * map.width();
  const std::int64_t h = s * map.height();
  if (w > kMaxTrajectoryImageSide || h > kMaxTrajectoryImageSide || w * h > kMaxTrajectoryImagePixels) {
    throw ConfigError(
        option, std::to_string(s) + " pixels per cell" + (scale == 0 ? " (automatic)" : "") + " on the " +
                    std::to_string(map.width()) + "x" + std::to_string(map.height()) + " map makes a " +
                    std::to_string(w) + "x" + std::to_string(h) + " image (" + std::to_string(w * h) +
                    " pixels); allowed: at most " + std::to_string(kMaxTrajectoryImageSide) +
                    " pixels per side and " + std::to_string(kMaxTrajectoryImagePixels) + " pixels in all");
  }
}

std::string trajectory_png(const WorldMap& map, const RunResult& result, int scale) {
  check_trajectory_image(map, scale, "scale");
  scale = trajectory_scale(map, scale);
  Canvas canvas(map.width(), map.height(), scale);
  const KnownMap& known = result.final_known;
  for (int i = 0; i < map.occupied.size(); ++i) {
    const Cell c = map.occupied.cell(i);
    const bool occ = map.occupied[i] != 0;
    const bool seen = known.size() == map.occupied.size() && known.state(i) != CellState::Unknown;
    canvas.cell(c, occ ? (seen ? Rgb{0, 0, 0} : Rgb{120, 120, 120})
                       : (seen ? Rgb{255, 255, 255} : Rgb{200, 200, 200}));
  }
  for (const int i : result.final_frontiers) canvas.cell(map.occupied.cell(i), Rgb{230, 0, 230});
  const auto& traj = result.trajectory;
  const int thick = std::max(1, scale / 3);
  for (std::size_t i = 1; i < traj.size(); ++i) {
    canvas.line(traj[i - 1], traj[i], time_colour(static_cast<double>(i) / static_cast<double>(traj.size())),
                thick);
  }
  const int mark = std::max(0, scale / 2 - 3);
  for (const int s : result.recharge_steps)
    canvas.cell(traj[static_cast<std::size_t>(s)], Rgb{0, 160, 0}, mark);
  // The dock: a green square three cells wide so it shows at any scale.
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx)
      canvas.cell(Cell{result.dock.x + dx, result.dock.y + dy}, Rgb{0, 170, 0});
  }
  return canvas.png();
}

void write_trajectory_png(const std::string& path, const WorldMap& map, const RunResult& result, int scale) {
  write_file_atomically(path, trajectory_png(map, result, scale));
}

}  // namespace sim
}  // namespace fsweep
