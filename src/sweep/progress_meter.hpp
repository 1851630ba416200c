#pragma once
/// @file progress_meter.hpp
/// Progress of a long job on stderr (docs/dev/architecture.md, "Command line"): on a terminal a one-line bar
/// `[#####.....] 123/400 runs, 45.6 runs/s, ETA 6 s` redrawn at most 10 times a second;
/// otherwise (a log file, a Slurm job) one line every 5 seconds.

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

namespace fsweep {
inline namespace sweep {

class ProgressMeter {
 public:
  using Clock = std::chrono::steady_clock;

  /// `total` units of work, of which `unit` names one ("runs"); `enabled` false = silent.
  /// Writes to `out` (stderr by default); the bar form is used when `out` is a terminal.
  ProgressMeter(std::uint64_t total, std::string unit, bool enabled, std::FILE* out = stderr);

  /// Reports `done` units finished so far, of which `skipped` were done before this job
  /// started (they count towards the bar, not towards the rate). Cheap when nothing is drawn.
  void update(std::uint64_t done, std::uint64_t skipped);
  /// Draws the final state and ends the line.
  void finish(std::uint64_t done, std::uint64_t skipped);

  /// The text of one report (without '\r' or newline), for tests: rate in units/s.
  [[nodiscard]] static std::string format(std::uint64_t done, std::uint64_t total, const std::string& unit,
                                          double rate, bool bar);
  /// "6 s", "3 min 12 s", "2 h 05 min", "4 d 3 h"; "?" for a negative or non-finite time.
  [[nodiscard]] static std::string format_duration(double seconds);

 private:
  void draw(std::uint64_t done, std::uint64_t skipped, bool final);

  std::uint64_t total_ = 0;
  std::string unit_;
  bool enabled_ = true;
  bool terminal_ = false;
  std::FILE* out_ = nullptr;
  Clock::time_point start_;
  Clock::time_point last_draw_;
  bool drawn_ = false;
};

}  // namespace sweep
}  // namespace fsweep
