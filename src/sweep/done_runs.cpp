#include "sweep/done_runs.hpp"

#include <algorithm>

#include "core/csv_reader.hpp"

namespace fsweep {
inline namespace sweep {

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
  return parse_unsigned(s, 16);
}

std::optional<std::uint64_t> parse_run_index(std::string_view s) { return parse_unsigned(s); }

}  // namespace sweep
}  // namespace fsweep
