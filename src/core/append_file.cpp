#include "core/append_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <string>

#include "core/files.hpp"
#include "core/io_error.hpp"

namespace fsweep {
inline namespace core {

AppendFile::~AppendFile() {
  if (fd_ >= 0) ::close(fd_);
}

void AppendFile::open() {
  if (fd_ >= 0) return;
  fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC | (create_ ? O_CREAT : 0), 0644);
  if (fd_ < 0) throw IoError(path_, "cannot open for appending", errno);
}

void AppendFile::write(std::string_view bytes) {
  open();
  // Where this append starts (O_APPEND writes at the end), to cut a partial append off again.
  const off_t start = ::lseek(fd_, 0, SEEK_END);
  if (start < 0) throw IoError(path_, "cannot find its end", errno);
  const int error = write_fully(fd_, bytes);
  if (error == 0) return;
  // A write(2) past a file size limit or onto a full disk stores what fits: without the cut,
  // the file would end in a torn record (the readers would repair it, but other programs
  // reading the file meanwhile would not). Shrinking needs no space and is not limited.
  (void)::ftruncate(fd_, start);
  throw IoError(path_, "write failed", error);
}

void AppendFile::close() {
  if (fd_ < 0) return;
  const int closed = ::close(fd_);
  fd_ = -1;  // Linux releases the descriptor even when close(2) fails
  if (closed != 0 && errno != EINTR) throw IoError(path_, "write failed", errno);
}

}  // namespace core
}  // namespace fsweep
