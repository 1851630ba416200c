#pragma once
/// @file append_file.hpp
/// A file that results are appended to, each append one or more whole write(2) calls, so that
/// a process killed at any moment leaves at most one torn record at the end. Shared by the
/// sweep's CSV journals (sweep/csv_journal.hpp) and the weight search's journal
/// (weightsearch/search_journal.hpp); each cuts its own torn tail when it reads the file.
///
/// An append the machine refuses (a full disk, a file size limit, a quota) leaves no torn
/// record: the part of it that was written is cut off again, and IoError names the file and
/// the OS error.

#include <string>
#include <string_view>
#include <utility>

namespace fsweep {
inline namespace core {

class AppendFile {
 public:
  /// Names `path`; nothing is opened before the first write(). `create`: a missing file is
  /// created (mode 0644); otherwise the first write() refuses it.
  explicit AppendFile(std::string path, bool create = true) : path_(std::move(path)), create_(create) {}
  AppendFile(const AppendFile&) = delete;
  AppendFile& operator=(const AppendFile&) = delete;
  /// Closes the file; an error of that close(2) goes unreported (call close() to see it).
  ~AppendFile();

  /// Opens the file for appending, if it is not open (write() does so itself): a caller that
  /// will write only after long work finds out at once that it cannot. Throws as write().
  void open();
  /// Appends `bytes` (opening the file for appending on the first call); returns once the kernel
  /// has them all. All or nothing: when a write(2) fails, the file is cut back to its size before
  /// the call, and IoError names the file and the OS error (a full disk, a read-only directory,
  /// a file size limit).
  void write(std::string_view bytes);
  /// Closes the file; the next write() opens it again (e.g. after it was renamed over). Throws
  /// IoError when close(2) reports an error (some file systems report a full disk only then).
  void close();

  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  std::string path_;
  bool create_ = true;
  int fd_ = -1;
};

}  // namespace core
}  // namespace fsweep
