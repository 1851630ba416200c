#include "core/replacing_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <utility>

#include "core/files.hpp"
#include "core/io_error.hpp"

namespace fsweep {
inline namespace core {
namespace {

/// Bytes gathered before a write(2): few calls for a file of many short rows.
constexpr std::size_t kBufferBytes = std::size_t{1} << 16;

}  // namespace

ReplacingFile::ReplacingFile(std::string path) : path_(std::move(path)), temp_(temp_path(path_)) {
  // 0666 less the umask, as std::ofstream created these files before.
  fd_ = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd_ < 0) throw IoError(path_, "cannot create its temp file", errno);
}

ReplacingFile::~ReplacingFile() {
  if (committed_) return;
  if (fd_ >= 0) ::close(fd_);
  if (!temp_.empty()) (void)std::remove(temp_.c_str());
}

void ReplacingFile::write(std::string_view bytes) {
  buffer_.append(bytes);
  if (buffer_.size() >= kBufferBytes) flush();
}

void ReplacingFile::flush() {
  if (const int error = write_fully(fd_, buffer_); error != 0) fail("write failed", error);
  buffer_.clear();
}

void ReplacingFile::commit() {
  flush();
  const int closed = ::close(fd_);
  fd_ = -1;
  if (closed != 0 && errno != EINTR) fail("write failed", errno);  // after EINTR the file is closed
  if (::rename(temp_.c_str(), path_.c_str()) != 0) fail("cannot put the new file in place", errno);
  committed_ = true;
}

void ReplacingFile::fail(const std::string& what_failed, int os_error) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  (void)std::remove(temp_.c_str());
  temp_.clear();
  throw IoError(path_, what_failed, os_error);
}

}  // namespace core
}  // namespace fsweep
