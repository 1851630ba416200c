// Fuzz target: image maps. By its first bytes the input is a PGM ("P2"/"P5": the bitmap loader
// at one cell per pixel), a PNG (its signature: likewise) or else a ROS map_server YAML, loaded
// with a valid 8x6 PGM beside it as `image.pgm` (the seeds' YAML files name other images;
// mutations find this one).
#include <cstdint>
#include <string>

#include "fuzz_support.hpp"
#include "world/map_loaders.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fsweep;
  static const bool image_written = [] {
    std::string pgm = "P5\n8 6\n255\n";
    for (int i = 0; i < 8 * 6; ++i) pgm += static_cast<char>(i % 7 == 0 ? 0 : 254);
    (void)fuzz::write_scratch("image.pgm", pgm);
    return true;
  }();
  (void)image_written;
  const std::string_view bytes = fuzz::as_text(data, size);
  if (bytes.starts_with("P2") || bytes.starts_with("P5")) {
    const std::string path = fuzz::write_scratch("input.pgm", bytes);
    fuzz::accept_clear_errors([&] { (void)load_bitmap(path, BitmapScale{1.0, 0.0, 0.0}, 127, 0.0); });
  } else if (bytes.starts_with("\x89PNG")) {
    const std::string path = fuzz::write_scratch("input.png", bytes);
    fuzz::accept_clear_errors([&] { (void)load_bitmap(path, BitmapScale{1.0, 0.0, 0.0}, 127, 0.0); });
  } else {
    const std::string path = fuzz::write_scratch("input.yaml", bytes);
    fuzz::accept_clear_errors([&] { (void)load_ros_map(path); });
  }
  return 0;
}
