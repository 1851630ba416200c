#include "core/shard_dirs.hpp"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <string_view>
#include <system_error>
#include <utility>

#include "core/csv_reader.hpp"

namespace fsweep {
inline namespace core {
namespace {

/// "<i>-of-<n>" after "shard-" as two whole numbers.
std::optional<std::pair<std::uint64_t, std::uint64_t>> shard_numbers(std::string_view name) {
  constexpr std::string_view kPrefix = "shard-";
  constexpr std::string_view kOf = "-of-";
  if (!name.starts_with(kPrefix)) return std::nullopt;
  name.remove_prefix(kPrefix.size());
  const std::size_t of = name.find(kOf);
  if (of == std::string_view::npos) return std::nullopt;
  const auto index = parse_unsigned(name.substr(0, of));
  const auto count = parse_unsigned(name.substr(of + kOf.size()));
  if (!index || !count) return std::nullopt;
  return std::pair{*index, *count};
}

}  // namespace

std::string shard_dir_name(std::uint64_t index, std::uint64_t count) {
  return "shard-" + std::to_string(index) + "-of-" + std::to_string(count);
}

std::vector<ShardDir> shard_dirs(const std::string& dir) {
  std::vector<ShardDir> out;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const auto numbers = shard_numbers(entry.path().filename().string());
    if (numbers && entry.is_directory(ec))
      out.push_back({numbers->first, numbers->second, entry.path().string()});
  }
  std::sort(out.begin(), out.end(), [](const ShardDir& a, const ShardDir& b) {
    return a.count != b.count ? a.count < b.count : a.index < b.index;
  });
  return out;
}

}  // namespace core
}  // namespace fsweep
