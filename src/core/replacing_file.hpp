#pragma once
/// @file replacing_file.hpp
/// A file written whole and then put in place: its bytes go to a temp file beside it
/// (temp_path()), which commit() renames over it, so that a reader, a kill or a failed write
/// sees the old file (or none), never part of the new one. Used for every file of a sweep that
/// is not appended to (manifest.json, summary.csv, the search files, journals put in run order).

#include <string>
#include <string_view>

namespace fsweep {
inline namespace core {

class ReplacingFile {
 public:
  /// Creates the temp file for `path`. Throws IoError naming `path` and the OS error when it
  /// cannot be (a read-only or missing directory, no space for a new file).
  explicit ReplacingFile(std::string path);
  ReplacingFile(const ReplacingFile&) = delete;
  ReplacingFile& operator=(const ReplacingFile&) = delete;
  /// Removes the temp file unless commit() put it in place: the old file stays.
  ~ReplacingFile();

  /// Adds `bytes` to the new file. Buffered: a full disk may surface here or at commit(), as an
  /// IoError naming `path` and the OS error, after which the temp file is gone.
  void write(std::string_view bytes);
  /// Writes what is buffered, closes the temp file (its close(2) checked too: some file systems
  /// report a full disk only then) and renames it over `path`. Throws IoError on any failure,
  /// leaving the old file and no temp file.
  void commit();

  /// The file this one replaces.
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  /// Writes the buffer to the temp file.
  void flush();
  /// Closes and removes the temp file, then throws IoError(path_, what_failed, os_error).
  [[noreturn]] void fail(const std::string& what_failed, int os_error);

  std::string path_;
  std::string temp_;
  std::string buffer_;
  int fd_ = -1;
  bool committed_ = false;
};

}  // namespace core
}  // namespace fsweep
