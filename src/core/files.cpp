#include "core/files.hpp"

#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <sstream>
#include <utility>

#include "core/replacing_file.hpp"

namespace fsweep {
inline namespace core {

std::string temp_path(const std::string& path) { return path + ".tmp." + std::to_string(::getpid()); }

void write_file_atomically(const std::string& path, std::string_view contents) {
  ReplacingFile file(path);
  file.write(contents);
  file.commit();
}

int write_fully(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return errno;
    // A write past a file size limit or onto a full disk writes what fits and returns its
    // count; the next one fails with the reason.
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return 0;
}

std::optional<std::string> read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return std::move(bytes).str();
}

std::string read_first_line(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::string line;
  if (!std::getline(in, line) || in.eof()) return {};  // no newline: not a complete line
  return line;
}

}  // namespace core
}  // namespace fsweep
