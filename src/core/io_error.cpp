#include "core/io_error.hpp"

#include <system_error>
#include <utility>

namespace fsweep {
inline namespace core {
namespace {

/// The OS's text for `os_error` ("No space left on device"); thread-safe, unlike strerror().
std::string os_text(int os_error) { return std::system_category().message(os_error); }

}  // namespace

IoError::IoError(std::string path, const std::string& what_failed, int os_error)
    : std::runtime_error(path + ": " + what_failed + ": " + os_text(os_error)),
      path_(std::move(path)),
      os_error_(os_error) {}

IoError::IoError(const IoError& base, const std::string& note)
    : std::runtime_error(std::string(base.what()) + " (" + note + ")"),
      path_(base.path_),
      os_error_(base.os_error_) {}

IoError IoError::with_note(const std::string& note) const { return {*this, note}; }

}  // namespace core
}  // namespace fsweep
