#include "sweep/progress_meter.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace fsweep {
inline namespace sweep {
namespace {

constexpr auto kTerminalInterval = std::chrono::milliseconds(100);  // at most 10 redraws/s
constexpr auto kLogInterval = std::chrono::seconds(5);
constexpr int kBarWidth = 30;

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, v);
  return buf;
}

}  // namespace

ProgressMeter::ProgressMeter(std::uint64_t total, std::string unit, bool enabled, std::FILE* out)
    : total_(total),
      unit_(std::move(unit)),
      enabled_(enabled),
      terminal_(enabled && ::isatty(::fileno(out)) != 0),
      out_(out),
      start_(Clock::now()),
      last_draw_(start_) {}

std::string ProgressMeter::format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  const auto s = static_cast<std::uint64_t>(std::llround(seconds));
  char buf[64];
  if (s < 60) {
    std::snprintf(buf, sizeof(buf), "%llu s", static_cast<unsigned long long>(s));
  } else if (s < 3600) {
    std::snprintf(buf, sizeof(buf), "%llu min %02llu s", static_cast<unsigned long long>(s / 60),
                  static_cast<unsigned long long>(s % 60));
  } else if (s < 86400) {
    std::snprintf(buf, sizeof(buf), "%llu h %02llu min", static_cast<unsigned long long>(s / 3600),
                  static_cast<unsigned long long>(s % 3600 / 60));
  } else {
    std::snprintf(buf, sizeof(buf), "%llu d %llu h", static_cast<unsigned long long>(s / 86400),
                  static_cast<unsigned long long>(s % 86400 / 3600));
  }
  return buf;
}

std::string ProgressMeter::format(std::uint64_t done, std::uint64_t total, const std::string& unit,
                                  double rate, bool bar) {
  std::string s;
  if (bar) {
    const double frac = total == 0 ? 1.0 : static_cast<double>(done) / static_cast<double>(total);
    const int filled = std::min(kBarWidth, static_cast<int>(frac * kBarWidth));
    s = "[" + std::string(static_cast<std::size_t>(filled), '#') +
        std::string(static_cast<std::size_t>(kBarWidth - filled), '.') + "] ";
  }
  s += std::to_string(done) + "/" + std::to_string(total) + " " + unit;
  if (!bar && total > 0)
    s += " (" + fixed(100.0 * static_cast<double>(done) / static_cast<double>(total), 1) + "%)";
  s += ", " + fixed(rate, rate < 10 ? 2 : 1) + " " + unit + "/s";
  const std::uint64_t left = total > done ? total - done : 0;
  if (left == 0) return s;
  return s + ", ETA " + (rate > 0 ? format_duration(static_cast<double>(left) / rate) : std::string("?"));
}

void ProgressMeter::draw(std::uint64_t done, std::uint64_t skipped, bool final) {
  const auto now = Clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double rate = elapsed > 0 ? static_cast<double>(done - std::min(done, skipped)) / elapsed : 0.0;
  const std::string text = format(done, total_, unit_, rate, terminal_);
  if (terminal_) {
    // \033[K clears what a longer previous line left behind.
    std::fprintf(out_, "\r%s\033[K%s", text.c_str(), final ? "\n" : "");
  } else {
    std::fprintf(out_, "%s\n", text.c_str());
  }
  std::fflush(out_);
  last_draw_ = now;
  drawn_ = true;
}

void ProgressMeter::update(std::uint64_t done, std::uint64_t skipped) {
  if (!enabled_) return;
  const auto now = Clock::now();
  if (now - last_draw_ < (terminal_ ? std::chrono::duration_cast<Clock::duration>(kTerminalInterval)
                                    : std::chrono::duration_cast<Clock::duration>(kLogInterval))) {
    return;
  }
  draw(done, skipped, false);
}

void ProgressMeter::finish(std::uint64_t done, std::uint64_t skipped) {
  if (!enabled_) return;
  draw(done, skipped, true);
}

}  // namespace sweep
}  // namespace fsweep
