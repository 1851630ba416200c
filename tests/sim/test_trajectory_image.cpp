/// The trajectory picture: a title band, the map, a legend band with a scale bar; the dock shows at
/// any map size.
#include <gtest/gtest.h>
#include <stb/stb_image.h>

#include <array>
#include <memory>

#include "sim/simulation.hpp"
#include "sim/trajectory_image.hpp"
#include "world/map_spec.hpp"

namespace fsweep {
namespace test_trajectory_image {

/// A decoded RGB picture.
struct Picture {
  int w = 0, h = 0;
  std::vector<unsigned char> rgb;
  [[nodiscard]] std::array<int, 3> at(int x, int y) const {
    const auto* p =
        &rgb[(static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) * 3];
    return {p[0], p[1], p[2]};
  }
  /// True when row y holds a pixel that is not white.
  [[nodiscard]] bool inked(int y, int x0, int x1) const {
    for (int x = x0; x < x1; ++x) {
      if (at(x, y) != std::array<int, 3>{255, 255, 255}) return true;
    }
    return false;
  }
};

Picture decode(const std::string& png) {
  Picture p;
  int channels = 0;
  unsigned char* data = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(png.data()),
                                              static_cast<int>(png.size()), &p.w, &p.h, &channels, 3);
  EXPECT_NE(data, nullptr);
  if (data != nullptr) {
    p.rgb.assign(data, data + static_cast<std::size_t>(p.w) * static_cast<std::size_t>(p.h) * 3);
    stbi_image_free(data);
  }
  return p;
}

RunResult run_on(const std::string& spec_text, RunSpec& spec) {
  spec.map = std::make_shared<const WorldMap>(load_map_spec(spec_text));
  spec.robot.sensor.range_m = 4;
  spec.robot.battery_capacity = 60;
  return simulate(spec);
}

TEST(TrajectoryImage, HasATitleTheMapAndALegendWithAScaleBar) {
  RunSpec spec;
  const RunResult result = run_on("rooms:w=40,h=30,door=3,seed=1", spec);
  const Picture p = decode(trajectory_png(*spec.map, result, 10, trajectory_title(spec)));
  // 40 x 30 cells of 10 pixels, text size 1 (lines of 10 pixels): 3.5 lines above, 3 below.
  EXPECT_EQ(p.w, 400);
  EXPECT_EQ(p.h, 300 + 35 + 30);
  EXPECT_TRUE(p.inked(3, 0, 400)) << "the title's first line";
  EXPECT_TRUE(p.inked(23, 0, 400)) << "the title's outcome line";
  EXPECT_TRUE(p.inked(300 + 35 + 7, 0, 400)) << "the legend";
  // The scale bar ends at the right, on the legend's second line: a black bar at mid height.
  const int bar_y = 300 + 35 + 5 + 10 + 3;
  bool bar = false;
  for (int x = 250; x < 400 && !bar; ++x) bar = p.at(x, bar_y) == std::array<int, 3>{0, 0, 0};
  EXPECT_TRUE(bar);
  // The dock (the map's start) is a green disc at its cell's centre.
  const Cell dock = result.dock;
  EXPECT_EQ(p.at(dock.x * 10 + 5, 35 + dock.y * 10 + 5), (std::array<int, 3>{0, 150, 0}));
}

TEST(TrajectoryImage, TheDockShowsOnALargeMap) {
  // 1000 x 1000 cells at one pixel each: the dock's disc is at least 1/120 of the picture's side.
  RunSpec spec;
  spec.map = std::make_shared<const WorldMap>(load_map_spec("free:w=1000,h=1000"));
  RunResult result;
  result.dock = spec.map->start;
  result.final_known = KnownMap(spec.map->width(), spec.map->height(), spec.map->resolution_m);
  const Picture p = decode(trajectory_png(*spec.map, result, 0));
  const int top = 70;  // the title band above the map: 3.5 lines of 20 pixels (text size 2 at 1000 wide)
  EXPECT_EQ(p.h, 1000 + 70 + 60);
  for (const int d : {0, 5}) {
    EXPECT_EQ(p.at(result.dock.x + d, top + result.dock.y), (std::array<int, 3>{0, 150, 0})) << d;
  }
}

}  // namespace test_trajectory_image
}  // namespace fsweep
