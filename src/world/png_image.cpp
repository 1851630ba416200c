#include "world/png_image.hpp"

#include <stb/stb_image_write.h>

#include <stdexcept>

namespace fsweep {
inline namespace world {

std::string encode_png(int width, int height, const std::vector<std::uint8_t>& rgb) {
  std::string bytes;
  const auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                               static_cast<std::size_t>(size));
  };
  if (stbi_write_png_to_func(append, &bytes, width, height, 3, rgb.data(), width * 3) == 0) {
    throw std::runtime_error("stb could not encode a PNG of " + std::to_string(width) + " x " +
                             std::to_string(height) + " pixels");
  }
  return bytes;
}

}  // namespace world
}  // namespace fsweep
