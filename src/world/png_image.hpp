#pragma once
/// @file png_image.hpp
/// PNG file bytes of an RGB picture, encoded by stb_image_write in memory, so that the file is
/// written whole and checked by write_file_atomically() (core/files.hpp) like every result file.

#include <cstdint>
#include <string>
#include <vector>

namespace fsweep {
inline namespace world {

/// The PNG bytes of a `width` x `height` picture, `rgb` its pixels row by row from the top, three
/// bytes each (size width * height * 3). Throws std::runtime_error when stb cannot encode it.
[[nodiscard]] std::string encode_png(int width, int height, const std::vector<std::uint8_t>& rgb);

}  // namespace world
}  // namespace fsweep
