#pragma once
/// @file file_size_limit_for_tests.hpp
/// A file size limit for this process (RLIMIT_FSIZE, as `ulimit -f` sets), with SIGXFSZ ignored
/// as fsweep ignores it, so a write past the limit fails with EFBIG instead of killing the test.

#include <sys/resource.h>

#include <csignal>

namespace fsweep {
namespace test_support {  // not anonymous: unity builds

/// Limits the files this process writes to `bytes` while it lives, SIGXFSZ ignored; then
/// restores both.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    ::getrlimit(RLIMIT_FSIZE, &old_);
    rlimit limit = old_;
    limit.rlim_cur = bytes;
    ok_ = ::setrlimit(RLIMIT_FSIZE, &limit) == 0;
    old_handler_ = std::signal(SIGXFSZ, SIG_IGN);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &old_);
    std::signal(SIGXFSZ, old_handler_);
  }
  [[nodiscard]] bool ok() const { return ok_; }

 private:
  rlimit old_{};
  void (*old_handler_)(int) = nullptr;
  bool ok_ = false;
};

}  // namespace test_support
}  // namespace fsweep
