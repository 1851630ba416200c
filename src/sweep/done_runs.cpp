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

void DoneRuns::add(std::uint64_t key, std::uint64_t index) { rows_.push_back({index, key}); }

void DoneRuns::seal() { std::sort(rows_.begin(), rows_.end()); }

namespace {

auto find_index(const std::vector<DoneRuns::Row>& rows, std::uint64_t index) {
  return std::lower_bound(rows.begin(), rows.end(), index,
                          [](const DoneRuns::Row& r, std::uint64_t i) { return r.index < i; });
}

}  // namespace

bool DoneRuns::contains(std::uint64_t key, std::uint64_t index) const {
  const auto it = find_index(rows_, index);
  return it != rows_.end() && it->index == index && it->key == key;
}

bool DoneRuns::has(std::uint64_t index) const {
  const auto it = find_index(rows_, index);
  return it != rows_.end() && it->index == index;
}

std::optional<std::uint64_t> parse_run_key(std::string_view s) {
  if (s.size() != 16) return std::nullopt;
  return parse_u64(s, 16);
}

std::optional<std::uint64_t> parse_run_index(std::string_view s) { return parse_u64(s, 10); }

}  // namespace sweep
}  // namespace fsweep
