/// @file image_map_loaders.cpp
/// Image-based maps: ROS map_server YAML + image, and PNG/PGM bitmaps (read with stb_image).
#include <stb/stb_image.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "core/config_error.hpp"
#include "world/loader_support.hpp"
#include "world/map_loaders.hpp"

namespace fsweep {
inline namespace world {
namespace {

using loader_detail::number_text;
using loader_detail::read_whole_file;
using loader_detail::require_map_size;
using loader_detail::require_positive_resolution;
using loader_detail::set_first_free_start;

/// An 8-bit image reduced to one grey channel: for each pixel the sum of its colour channels
/// (alpha ignored) and the channel count, so that the mean `sum / channels` stays exact.
struct GreyImage {
  int width = 0;
  int height = 0;
  int channels = 1;
  std::vector<std::uint16_t> sum;  // row-major, row 0 is the top of the image

  [[nodiscard]] double mean(int x, int y) const {
    return static_cast<double>(sum[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                                   static_cast<std::size_t>(x)]) /
           channels;
  }
};

/// The header of a binary PGM/PPM (P5/P6): "P5", width, height, maxval, each after whitespace
/// or '#' comments, then one whitespace byte before the pixel data.
struct PnmHeader {
  std::int64_t width = 0;
  std::int64_t height = 0;
  int channels = 1;          // P5: 1, P6: 3
  int bytes_per_sample = 1;  // maxval < 256: 1, else 2
  std::size_t data_offset = 0;
};

/// The header of `bytes` if they start with a binary PGM/PPM's magic ("P5"/"P6"); nullopt for
/// other formats (stb_image reads them). A malformed header is a ConfigError naming `path`: stb_image
/// would read some of them its own way (a field ended by a stray byte) and take a few bytes for
/// an image of 10^8 pixels.
std::optional<PnmHeader> read_pnm_header(const std::string& bytes, const std::string& path) {
  if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != '5' && bytes[1] != '6')) return std::nullopt;
  PnmHeader h;
  h.channels = bytes[1] == '5' ? 1 : 3;
  std::size_t i = 2;
  std::array<std::int64_t, 3> fields{};  // width, height, maxval
  constexpr std::array<const char*, 3> kNames{"width", "height", "maxval"};
  const auto malformed = [&](std::size_t k, const std::string& what) {
    return ConfigError(path, std::string("the P") + bytes[1] + " header is malformed: its " + kNames.at(k) +
                                 " " + what +
                                 "; allowed: P5 or P6, then width, height and maxval (1 to 65535) as decimal "
                                 "numbers separated by whitespace or # comments, then one whitespace byte");
  };
  for (std::size_t k = 0; k < fields.size(); ++k) {
    std::int64_t& field = fields.at(k);
    while (i < bytes.size() && (std::isspace(static_cast<unsigned char>(bytes[i])) != 0 || bytes[i] == '#')) {
      if (bytes[i] == '#') {
        while (i < bytes.size() && bytes[i] != '\n') ++i;
      } else {
        ++i;
      }
    }
    const std::size_t begin = i;
    // At most 12 digits: enough for any size this loader could accept, and no overflow.
    while (i < bytes.size() && i - begin < 12 && std::isdigit(static_cast<unsigned char>(bytes[i])) != 0) {
      field = field * 10 + (bytes[i] - '0');
      ++i;
    }
    if (i == begin) {
      throw malformed(k, i < bytes.size() ? "is missing (byte " + std::to_string(i) + " is not a digit)"
                                          : "is missing (the file ends)");
    }
    if (i >= bytes.size()) throw malformed(k, "is the end of the file");
    if (std::isdigit(static_cast<unsigned char>(bytes[i])) != 0)
      throw malformed(k, "has more than 12 digits");
    if (std::isspace(static_cast<unsigned char>(bytes[i])) == 0) {
      char hex[8];
      std::snprintf(hex, sizeof(hex), "0x%02x", static_cast<unsigned>(static_cast<unsigned char>(bytes[i])));
      throw malformed(k, "is followed by byte " + std::string(hex) + " at offset " + std::to_string(i) +
                             ", not whitespace");
    }
  }
  if (fields[2] < 1 || fields[2] > 65535) throw malformed(2, "is " + std::to_string(fields[2]));
  h.width = fields[0];
  h.height = fields[1];
  h.bytes_per_sample = fields[2] < 256 ? 1 : 2;
  h.data_offset = i + 1;
  return h;
}

/// Reads a PNG or PGM (or any format stb_image knows) as grey; 16-bit images are scaled to 8 bits.
/// The declared size is checked before decoding: at most kMaxMapCells pixels and, for a PGM/PPM,
/// all of its pixel bytes present.
GreyImage load_grey_image(const std::string& path) {
  const std::string bytes = read_whole_file(path, "cannot read the image: cannot open the file");
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int length = static_cast<int>(std::min<std::size_t>(bytes.size(), std::numeric_limits<int>::max()));
  if (const std::optional<PnmHeader> pnm = read_pnm_header(bytes, path)) {
    require_map_size(pnm->width, pnm->height, path);
    const auto expected = static_cast<std::size_t>(pnm->width * pnm->height) *
                          static_cast<std::size_t>(pnm->channels * pnm->bytes_per_sample);
    const std::size_t present = bytes.size() - std::min(bytes.size(), pnm->data_offset);
    if (present < expected) {
      throw ConfigError(path, "the pixel data is cut short: the header declares " +
                                  std::to_string(pnm->width) + " x " + std::to_string(pnm->height) +
                                  " pixels, " + std::to_string(expected) + " bytes, but only " +
                                  std::to_string(present) + " bytes follow it");
    }
  }
  int w = 0;
  int h = 0;
  int n = 0;
  if (stbi_info_from_memory(data, length, &w, &h, &n) != 0) require_map_size(w, h, path);
  const std::unique_ptr<stbi_uc, decltype(&stbi_image_free)> pixels(
      stbi_load_from_memory(data, length, &w, &h, &n, 0), &stbi_image_free);
  if (!pixels) {
    const char* reason = stbi_failure_reason();
    throw ConfigError(path, std::string("cannot read the image (") +
                                (reason != nullptr ? reason : "unknown") +
                                "); allowed: 8- or 16-bit PNG or binary PGM (P5)");
  }
  GreyImage image;
  image.width = w;
  image.height = h;
  // Grey (1), grey+alpha (2) -> the grey channel; RGB (3), RGBA (4) -> the mean of R, G, B.
  image.channels = n >= 3 ? 3 : 1;
  const std::size_t count = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  image.sum.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const stbi_uc* p = pixels.get() + i * static_cast<std::size_t>(n);
    image.sum[i] = image.channels == 3 ? static_cast<std::uint16_t>(p[0] + p[1] + p[2]) : p[0];
  }
  return image;
}

/// "<path>:<line>:<column>" of a yaml-cpp mark (counted from 0 there, from 1 here); the path
/// alone for a mark yaml-cpp did not set.
std::string at_mark(const std::string& path, const YAML::Mark& mark) {
  if (mark.is_null() || mark.line < 0) return path;
  return path + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
}

/// A YAML node for messages: a scalar quoted and cut to 80 characters (before it is formatted),
/// otherwise its kind.
std::string yaml_text(const YAML::Node& node) {
  constexpr std::size_t kMaxText = 80;
  if (node.IsScalar()) {
    const std::string& s = node.Scalar();
    return "'" + (s.size() > kMaxText ? s.substr(0, kMaxText) + "..." : s) + "'";
  }
  if (node.IsSequence()) return "a sequence";
  if (node.IsMap()) return "a mapping";
  return "nothing";
}

/// A YAML scalar as T, or a ConfigError naming the file, the key and its line and column.
template <typename T>
T yaml_value(const YAML::Node& node, const std::string& key, const std::string& path, const char* expected) {
  try {
    return node.as<T>();
  } catch (const YAML::Exception&) {
    throw ConfigError(at_mark(path, node.Mark()),
                      "'" + key + "' must be " + expected + ", got " + yaml_text(node));
  }
}

}  // namespace

WorldMap load_ros_map(const std::string& yaml_path) {
  YAML::Node doc;
  try {
    doc = YAML::LoadFile(yaml_path);
  } catch (const YAML::BadFile&) {
    throw ConfigError(yaml_path, "cannot open the file for reading");
  } catch (const YAML::Exception& e) {
    // e.msg is yaml-cpp's reason without its "yaml-cpp: error at line ..." prefix.
    throw ConfigError(at_mark(yaml_path, e.mark), "invalid YAML: " + e.msg);
  }
  if (!doc.IsMap()) throw ConfigError(yaml_path, "expected a YAML mapping with image, resolution, ... keys");
  const auto required = [&](const std::string& key) {
    const YAML::Node node = doc[key];
    if (!node) {
      throw ConfigError(yaml_path, "missing key '" + key +
                                       "'; a ROS map needs image, resolution, occupied_thresh, free_thresh");
    }
    return node;
  };
  // Unknown keys (origin and anything else) are ignored: they do not affect the grid.
  const auto image_name = yaml_value<std::string>(required("image"), "image", yaml_path, "a file name");
  const auto resolution_m = yaml_value<double>(required("resolution"), "resolution", yaml_path, "a number");
  const auto occupied_thresh =
      yaml_value<double>(required("occupied_thresh"), "occupied_thresh", yaml_path, "a number");
  const auto free_thresh = yaml_value<double>(required("free_thresh"), "free_thresh", yaml_path, "a number");
  bool negate = false;
  if (const YAML::Node node = doc["negate"]) {
    // map_server writes 0/1; YAML true/false is accepted too.
    int as_int = 0;
    if (YAML::convert<int>::decode(node, as_int) && (as_int == 0 || as_int == 1)) {
      negate = as_int == 1;
    } else {
      negate = yaml_value<bool>(node, "negate", yaml_path, "0, 1, true or false");
    }
  }
  if (const YAML::Node node = doc["mode"]) {
    const auto mode = yaml_value<std::string>(node, "mode", yaml_path, "a string");
    if (mode != "trinary" && mode != "scale") {
      throw ConfigError(
          at_mark(yaml_path, node.Mark()),
          "mode " + yaml_text(node) + " is not supported; allowed: trinary, scale (thresholded alike)");
    }
  }
  require_positive_resolution(resolution_m, yaml_path);
  if (!(0.0 <= free_thresh && free_thresh < occupied_thresh && occupied_thresh <= 1.0)) {
    throw ConfigError(yaml_path, "thresholds free_thresh " + number_text(free_thresh) +
                                     " and occupied_thresh " + number_text(occupied_thresh) +
                                     " are not allowed; need 0 <= free_thresh < occupied_thresh <= 1");
  }
  std::filesystem::path image_path(image_name);
  if (image_path.is_relative()) image_path = std::filesystem::path(yaml_path).parent_path() / image_path;
  const GreyImage image = load_grey_image(image_path.string());

  WorldMap map;
  map.occupied = Grid<std::uint8_t>(image.width, image.height, 1);
  map.resolution_m = resolution_m;
  map.source = yaml_path;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      // map_server: p = (255 - v) / 255 is the occupancy probability (v / 255 when negated);
      // free below free_thresh, occupied above occupied_thresh, unknown between -> occupied here.
      const double v = image.mean(x, y);
      const double p = negate ? v / 255.0 : (255.0 - v) / 255.0;
      map.occupied.at(Cell{x, y}) = p < free_thresh ? 0 : 1;
    }
  }
  set_first_free_start(map);
  return map;
}

WorldMap load_bitmap(const std::string& path, const BitmapScale& scale, int threshold, double resolution_m) {
  if (threshold < 0 || threshold > 255) {
    throw ConfigError(path, "threshold " + std::to_string(threshold) + " is not allowed; allowed: 0..255");
  }
  const bool by_pixel = scale.metres_per_pixel > 0.0;
  const bool by_size = scale.width_m > 0.0 || scale.height_m > 0.0;
  if (by_pixel == by_size || (by_size && !(scale.width_m > 0.0 && scale.height_m > 0.0))) {
    throw ConfigError(path,
                      "give the bitmap scale either as metres per pixel (> 0) or as the image's width "
                      "and height in metres (both > 0), not both and not neither");
  }
  const GreyImage image = load_grey_image(path);
  const double mpp_x = by_pixel ? scale.metres_per_pixel : scale.width_m / image.width;
  const double mpp_y = by_pixel ? scale.metres_per_pixel : scale.height_m / image.height;
  const auto pixel_free = [&](int x, int y) {
    return image.sum[static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                     static_cast<std::size_t>(x)] > threshold * image.channels;
  };

  WorldMap map;
  map.source = path;
  if (resolution_m <= 0.0) {
    // One pixel per cell: only when the pixels are square.
    if (std::abs(mpp_x - mpp_y) > 1e-9 * std::max(mpp_x, mpp_y)) {
      throw ConfigError(path, "pixels are " + number_text(mpp_x) + " x " + number_text(mpp_y) +
                                  " m, not square; give a cell resolution to resample");
    }
    map.resolution_m = mpp_x;
    map.occupied = Grid<std::uint8_t>(image.width, image.height, 1);
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) map.occupied.at(Cell{x, y}) = pixel_free(x, y) ? 0 : 1;
    }
    set_first_free_start(map);
    return map;
  }
  require_positive_resolution(resolution_m, path);
  // Cell c covers [c * res, (c + 1) * res) metres and pixel p covers [p * mpp, (p + 1) * mpp); a cell
  // pools every pixel it overlaps by more than a rounding error. The last cell may extend past
  // the image; only its pixels inside the image count.
  constexpr double kEps = 1e-6;
  const double cells_x = std::ceil(image.width * mpp_x / resolution_m - kEps);
  const double cells_y = std::ceil(image.height * mpp_y / resolution_m - kEps);
  if (cells_x * cells_y > static_cast<double>(loader_detail::kMaxMapCells)) {
    throw ConfigError(path, "resampling to " + number_text(resolution_m) + " m cells gives " +
                                number_text(cells_x) + "x" + number_text(cells_y) +
                                " cells; allowed: at most 100000000");
  }
  const int width = static_cast<int>(cells_x);
  const int height = static_cast<int>(cells_y);
  const auto pixel_span = [&](int c, double mpp, int pixels) {
    const int lo = static_cast<int>(std::floor(c * resolution_m / mpp + kEps));
    const int hi = static_cast<int>(std::ceil((c + 1) * resolution_m / mpp - kEps));
    return std::pair<int, int>{std::clamp(lo, 0, pixels), std::clamp(std::max(hi, lo + 1), 0, pixels)};
  };
  map.resolution_m = resolution_m;
  map.occupied = Grid<std::uint8_t>(width, height, 0);
  for (int cy = 0; cy < height; ++cy) {
    const auto [y0, y1] = pixel_span(cy, mpp_y, image.height);
    for (int cx = 0; cx < width; ++cx) {
      const auto [x0, x1] = pixel_span(cx, mpp_x, image.width);
      bool occupied = false;
      for (int y = y0; y < y1 && !occupied; ++y) {
        for (int x = x0; x < x1 && !occupied; ++x) occupied = !pixel_free(x, y);
      }
      map.occupied.at(Cell{cx, cy}) = occupied ? 1 : 0;
    }
  }
  set_first_free_start(map);
  return map;
}

}  // namespace world
}  // namespace fsweep
