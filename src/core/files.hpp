#pragma once
/// @file files.hpp
/// Whole-file helpers shared by every layer that writes results. A file the machine does not let
/// them write (a full disk, a file size limit, a read-only directory) throws IoError
/// (core/io_error.hpp) naming it and the OS error.

#include <optional>
#include <string>
#include <string_view>

namespace fsweep {
inline namespace core {

/// A temp file name beside `path`, unique to this process: `path` + ".tmp." + pid.
[[nodiscard]] std::string temp_path(const std::string& path);

/// Writes `contents` to `path` atomically: a temp file in the same directory, then rename
/// (core/replacing_file.hpp). Throws IoError naming the file and the OS error; the old file is
/// then left as it was.
void write_file_atomically(const std::string& path, std::string_view contents);

/// Writes all of `bytes` to the open file `fd`, again after a signal interrupted a write(2);
/// returns 0, or the errno of the write(2) that failed (part of `bytes` may have been written).
[[nodiscard]] int write_fully(int fd, std::string_view bytes);

/// The whole file's bytes; nullopt when it cannot be opened or read.
[[nodiscard]] std::optional<std::string> read_file(const std::string& path);

/// The first line of a file without its newline; empty when the file is missing or has no
/// complete first line.
[[nodiscard]] std::string read_first_line(const std::string& path);

}  // namespace core
}  // namespace fsweep
