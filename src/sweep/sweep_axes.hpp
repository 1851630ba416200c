#pragma once
/// @file sweep_axes.hpp
/// Internal to engine/sweep: parsing and validation of each axis of a sweep file (the format
/// is documented in sweep_plan.hpp). Every function appends problems as "<JSON path>: message"
/// to `problems` and returns what it could parse; callers throw when `problems` is not empty.

#include <filesystem>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sweep/sweep_plan.hpp"

namespace fsweep {
inline namespace sweep {
namespace sweep_detail {

/// A JSON value for messages: json_excerpt() cut to 77 characters and "...", bounded in size and depth.
[[nodiscard]] std::string value_text(const nlohmann::json& v);

/// `message` without a leading "<path>: " (ConfigErrors from the plugins repeat the path of
/// the parameter; the sweep reports the more precise path of the offending value instead).
[[nodiscard]] std::string strip_path(const std::string& message, const std::string& path);

/// Path of value k of a sweep value written at `where`: `where` for a scalar, `where/k` for a
/// list, `where/range` for a range.
[[nodiscard]] std::string value_path(const nlohmann::json& written, const std::string& where, std::size_t k);

/// The parts joined into one string (messages and paths built in loops).
[[nodiscard]] std::string concat(std::initializer_list<std::string_view> parts);

/// 12,345,678.
[[nodiscard]] std::string with_thousands(std::uint64_t n);

/// Where the relative paths of a sweep file (map files, dataset folders, id lists) are found: in
/// the sweep file's folder (as CMake, Compose and Hydra resolve theirs), else, for sweeps written
/// when they were relative to the working directory, there, with a warning.
class SweepPaths {
 public:
  /// `sweep_file`: the path the sweep was read from; "" or a bare name: the working directory.
  explicit SweepPaths(const std::string& sweep_file);
  enum class Kind { File, Folder };
  /// The path to open for `written` (a path as the sweep gives it at JSON path `where`): itself
  /// when absolute or when the sweep file's folder is the working directory; else under the
  /// sweep file's folder when it is there, else under the working directory when it is there
  /// (a warning). A relative path in neither: a problem naming the absolute paths tried, and
  /// nullopt.
  [[nodiscard]] std::optional<std::string> resolve(const std::string& written, Kind kind,
                                                   const std::string& where,
                                                   std::vector<std::string>& problems);
  /// The warnings, one per path read from the working directory, with the path to write instead.
  [[nodiscard]] const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  std::filesystem::path folder_;  ///< the sweep file's folder ("" for the working directory)
  bool folder_is_cwd_ = true;
  std::vector<std::string> warnings_;
};

/// `maps`: loads every map (see sweep_plan.hpp), relative paths found by `paths`; plans of
/// dataset items skipped by `"on_bad_map": "skip"` go to `skipped`. `competitive`: the sweep's
/// top-level setting, which an item's own `competitive` overrides (SweepMap::competitive).
[[nodiscard]] std::vector<SweepMap> parse_maps(const nlohmann::json& maps, SweepPaths& paths,
                                               std::vector<std::string>& problems,
                                               std::vector<SkippedMap>& skipped, bool competitive = false);

/// `strategies`: entries with their parameter groups, each axis value validated; the files of
/// `"vectors": {"file": ...}` found by `paths`.
[[nodiscard]] std::vector<StrategyEntry> parse_strategies(const nlohmann::json& strategies, SweepPaths& paths,
                                                          std::vector<std::string>& problems);

/// `planners` (null: the default [{"type": "astar"}]).
[[nodiscard]] std::vector<SweepPlanner> parse_planners(const nlohmann::json& planners,
                                                       std::vector<std::string>& problems);

/// `robot` (null: {}): the cartesian product of its swept leaves, each variant validated.
[[nodiscard]] std::vector<RobotVariant> parse_robots(const nlohmann::json& robot,
                                                     std::vector<std::string>& problems);

}  // namespace sweep_detail
}  // namespace sweep
}  // namespace fsweep
