#include "core/memory_watch.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace fsweep {
inline namespace core {

MemoryWatch::MemoryWatch(std::uint64_t limit_bytes, Reader resident, const std::atomic<bool>* also,
                         std::chrono::milliseconds interval)
    : threshold_(std::max<std::uint64_t>(
          1, static_cast<std::uint64_t>(std::floor(kMemorySafetyShare * static_cast<double>(limit_bytes))))),
      resident_(std::move(resident)),
      also_(also) {
  if (limit_bytes == 0) throw std::invalid_argument("MemoryWatch: the limit must be > 0 bytes");
  if (!resident_) throw std::invalid_argument("MemoryWatch: no reader of the memory in use");
  if (also_ != nullptr && also_->load()) stop_.store(true);  // already stopped: at once
  thread_ = std::thread([this, interval] { watch(interval); });
}

MemoryWatch::~MemoryWatch() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    done_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

bool MemoryWatch::check() {
  if (reached_.load() != 0) return true;
  const std::optional<std::uint64_t> bytes = resident_();
  if (!bytes || *bytes < threshold_) return false;
  std::uint64_t none = 0;
  (void)reached_.compare_exchange_strong(none, *bytes);  // the first to reach it is the one reported
  stop_.store(true);
  return true;
}

std::optional<std::uint64_t> MemoryWatch::reached() const {
  const std::uint64_t bytes = reached_.load();
  return bytes == 0 ? std::nullopt : std::optional<std::uint64_t>(bytes);
}

void MemoryWatch::watch(std::chrono::milliseconds interval) {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, interval, [this] { return done_; })) {
    if (also_ != nullptr && also_->load()) stop_.store(true);
    (void)check();
  }
}

}  // namespace core
}  // namespace fsweep
