#pragma once
/// @file memory_watch.hpp
/// A guard against running out of memory: it reads the process's memory in use on a thread of
/// its own (and whenever asked) and, once that reaches a safety share of a limit, sets a stop
/// flag that a long computation polls (the exact weight search's `stop`), so the computation
/// ends as a Ctrl-C ends it, with its journal whole, instead of being killed by the kernel.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>

namespace fsweep {
inline namespace core {

/// The share of the limit past which the guard stops: the rest covers what the process's
/// resident memory does not show but the limit counts (other processes of the cgroup, the kernel's
/// own memory for them), the growth between two reads and while the stopped computation winds
/// down (the exact weight search grows by a few MB a second: docs/weight-search.md, "Memory").
inline constexpr double kMemorySafetyShare = 0.9;

/// How often the watch's thread reads the memory and forwards the caller's stop flag (a read of
/// /proc/self/statm takes a few microseconds).
inline constexpr std::chrono::milliseconds kMemoryWatchInterval{50};

class MemoryWatch {
 public:
  /// The memory in use in bytes; nullopt when it cannot be read (such a read never stops).
  using Reader = std::function<std::optional<std::uint64_t>()>;

  /// Starts watching: every `interval`, `resident` against kMemorySafetyShare x `limit_bytes`
  /// (> 0), and `also` (the caller's own stop flag, e.g. set by SIGINT; may be null), which it
  /// forwards to stop().
  MemoryWatch(std::uint64_t limit_bytes, Reader resident, const std::atomic<bool>* also,
              std::chrono::milliseconds interval = kMemoryWatchInterval);
  MemoryWatch(const MemoryWatch&) = delete;
  MemoryWatch& operator=(const MemoryWatch&) = delete;
  /// Stops the thread.
  ~MemoryWatch();

  /// The flag for the computation to poll: set once the memory reached the threshold or `also`
  /// was set.
  [[nodiscard]] const std::atomic<bool>* stop() const { return &stop_; }

  /// Reads the memory now (from any thread); true when it has reached the threshold, now or
  /// before, which sets stop().
  bool check();

  /// The memory in use when it first reached the threshold; nullopt while it has not.
  [[nodiscard]] std::optional<std::uint64_t> reached() const;

  /// kMemorySafetyShare x the limit, in bytes (at least 1).
  [[nodiscard]] std::uint64_t threshold_bytes() const { return threshold_; }

 private:
  void watch(std::chrono::milliseconds interval);

  const std::uint64_t threshold_;
  const Reader resident_;
  const std::atomic<bool>* also_;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> reached_{0};  // 0: not yet
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  std::thread thread_;
};

}  // namespace core
}  // namespace fsweep
