#pragma once
/// @file files.hpp
/// Whole-file helpers shared by every layer that writes results.

#include <fstream>
#include <optional>
#include <string>
#include <string_view>

namespace fsweep {
inline namespace core {

/// A temp file name beside `path`, unique to this process: `path` + ".tmp." + pid.
[[nodiscard]] std::string temp_path(const std::string& path);

/// `path` opened for binary writing, truncated; throws ConfigError at `path` when it cannot be.
[[nodiscard]] std::ofstream open_for_writing(const std::string& path);

/// Writes `contents` to `path` atomically: a temp file in the same directory, then rename.
/// Throws ConfigError naming the file on an error.
void write_file_atomically(const std::string& path, std::string_view contents);

/// The whole file's bytes; nullopt when it cannot be opened or read.
[[nodiscard]] std::optional<std::string> read_file(const std::string& path);

/// The first line of a file without its newline; empty when the file is missing or has no
/// complete first line.
[[nodiscard]] std::string read_first_line(const std::string& path);

}  // namespace core
}  // namespace fsweep
