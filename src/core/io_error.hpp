#pragma once
/// @file io_error.hpp
/// A file the machine would not let fsweep write: a full disk, a file size limit, a read-only
/// directory, a quota. It is not the user's input (that is ConfigError, exit 2): the command
/// line exits 1 on it, with a message naming the file and the OS error.

#include <stdexcept>
#include <string>

namespace fsweep {
inline namespace core {

class IoError : public std::runtime_error {
 public:
  /// "<path>: <what_failed>: <the OS's text for os_error>", e.g. "results/x/runs.csv: write
  /// failed: File too large". `os_error`: the errno of the call that failed.
  IoError(std::string path, const std::string& what_failed, int os_error);

  /// The same error with `note` (what to do about it) appended in parentheses.
  [[nodiscard]] IoError with_note(const std::string& note) const;

  /// The file that could not be written.
  [[nodiscard]] const std::string& path() const { return path_; }
  /// The errno of the call that failed (ENOSPC, EFBIG, EROFS, EDQUOT, ...).
  [[nodiscard]] int os_error() const { return os_error_; }

 private:
  IoError(const IoError& base, const std::string& note);

  std::string path_;
  int os_error_ = 0;
};

}  // namespace core
}  // namespace fsweep
