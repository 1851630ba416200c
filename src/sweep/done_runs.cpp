#include "sweep/done_runs.hpp"

#include <algorithm>
#include <charconv>

namespace fsweep {
inline namespace sweep {
namespace {

std::optional<std::uint64_t> parse_u64(std::string_view s, int base) {
  std::uint64_t v = 0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v, base);
  if (ec != std::errc() || ptr != s.data() + s.size() || s.empty()) return std::nullopt;
  return v;
}

}  // namespace

void DoneRuns::add(std::uint64_t key, std::uint64_t index) { rows_.push_back({key, index}); }

void DoneRuns::seal() {
  std::sort(rows_.begin(), rows_.end());
  taken_.assign(rows_.size(), false);
  taken_count_ = 0;
}

bool DoneRuns::contains(std::uint64_t key, std::uint64_t index) const {
  return std::binary_search(rows_.begin(), rows_.end(), Row{key, index});
}

bool DoneRuns::take(std::uint64_t key) {
  auto it = std::lower_bound(rows_.begin(), rows_.end(), Row{key, 0});
  for (; it != rows_.end() && it->key == key; ++it) {
    const auto i = static_cast<std::size_t>(it - rows_.begin());
    if (!taken_[i]) {
      taken_[i] = true;
      ++taken_count_;
      return true;
    }
  }
  return false;
}

std::optional<std::uint64_t> parse_run_key(std::string_view s) {
  if (s.size() != 16) return std::nullopt;
  return parse_u64(s, 16);
}

std::optional<std::uint64_t> parse_run_index(std::string_view s) { return parse_u64(s, 10); }

}  // namespace sweep
}  // namespace fsweep
