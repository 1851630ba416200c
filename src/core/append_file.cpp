#include "core/append_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "core/config_error.hpp"

namespace fsweep {
inline namespace core {

void AppendFile::open() {
  if (fd_ >= 0) return;
  fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC | (create_ ? O_CREAT : 0), 0644);
  if (fd_ < 0) throw ConfigError(path_, std::string("cannot open for appending: ") + std::strerror(errno));
}

void AppendFile::write(std::string_view bytes) {
  open();
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      throw ConfigError(path_, std::string("write failed: ") + std::strerror(errno));
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
}

void AppendFile::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

}  // namespace core
}  // namespace fsweep
