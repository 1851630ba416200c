// The memory guard: it stops at 90% of its limit, reports the memory it saw then, forwards the
// caller's own stop flag, and watches on its own thread. The memory is a number the test sets.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <optional>
#include <thread>

#include "core/memory_watch.hpp"

namespace fsweep {
namespace test_memory_watch {  // not anonymous: unity builds

/// A watch whose thread never wakes during a test: only check() reads the memory.
constexpr std::chrono::hours kNever{24};

/// True once `flag` is set, polled for up to a minute (a watch's thread sets it).
bool becomes_set(const std::atomic<bool>& flag) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  while (!flag.load() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return flag.load();
}

TEST(MemoryWatch, StopsOnceTheMemoryReachesNinetyPercentOfTheLimit) {
  std::atomic<std::uint64_t> in_use{899};
  MemoryWatch watch(
      1000, [&] { return std::optional<std::uint64_t>(in_use.load()); }, nullptr, kNever);
  EXPECT_EQ(watch.threshold_bytes(), 900U);
  EXPECT_FALSE(watch.check());
  EXPECT_FALSE(watch.stop()->load());
  EXPECT_EQ(watch.reached(), std::nullopt);
  in_use = 900;
  EXPECT_TRUE(watch.check());
  EXPECT_TRUE(watch.stop()->load());
  EXPECT_EQ(watch.reached(), 900U);
  // Reached once is reached: memory freed since does not take it back, nor change what it saw.
  in_use = 10;
  EXPECT_TRUE(watch.check());
  EXPECT_EQ(watch.reached(), 900U);
}

TEST(MemoryWatch, MemoryThatCannotBeReadNeverStops) {
  MemoryWatch watch(
      1000, [] { return std::optional<std::uint64_t>(); }, nullptr, kNever);
  EXPECT_FALSE(watch.check());
  EXPECT_FALSE(watch.stop()->load());
}

TEST(MemoryWatch, ForwardsTheCallersStopWithoutReachingTheLimit) {
  std::atomic<bool> interrupted{true};  // set before the watch starts: stopped at once
  const MemoryWatch early(
      1000, [] { return std::optional<std::uint64_t>(1); }, &interrupted, kNever);
  EXPECT_TRUE(early.stop()->load());
  EXPECT_EQ(early.reached(), std::nullopt);

  interrupted = false;
  const MemoryWatch later(
      1000, [] { return std::optional<std::uint64_t>(1); }, &interrupted, std::chrono::milliseconds(1));
  EXPECT_FALSE(later.stop()->load());
  interrupted = true;  // as SIGINT's handler sets it
  EXPECT_TRUE(becomes_set(*later.stop()));
  EXPECT_EQ(later.reached(), std::nullopt);
}

TEST(MemoryWatch, ItsThreadReadsTheMemoryWithoutBeingAsked) {
  std::atomic<std::uint64_t> in_use{100};
  const MemoryWatch watch(
      1000, [&] { return std::optional<std::uint64_t>(in_use.load()); }, nullptr,
      std::chrono::milliseconds(1));
  in_use = 950;
  EXPECT_TRUE(becomes_set(*watch.stop()));
  EXPECT_EQ(watch.reached(), 950U);
}

TEST(MemoryWatch, ALimitOfNoBytesIsRefused) {
  EXPECT_THROW(MemoryWatch(
                   0, [] { return std::optional<std::uint64_t>(1); }, nullptr),
               std::invalid_argument);
}

}  // namespace test_memory_watch
}  // namespace fsweep
