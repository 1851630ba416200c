#pragma once
/// @file manifest.hpp
/// manifest.json of a sweep's output directory (layout in sweep_runner.hpp): what was run, on
/// what, by which build, and how it went.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace fsweep {
inline namespace sweep {

class SweepPlan;

/// Run counts of a sweep (or shard) as the manifest reports them.
struct ManifestCounts {
  std::uint64_t total = 0;    ///< runs in the sweep (or shard)
  std::uint64_t done = 0;     ///< runs with a row in runs.csv (skipped + ran)
  std::uint64_t skipped = 0;  ///< already done when this invocation started
  std::uint64_t ran = 0;      ///< simulated by this invocation
  std::uint64_t failed = 0;   ///< rows in runs.csv whose end_reason is `error`
};

/// Everything the manifest records besides the plan and the build.
struct ManifestInfo {
  std::string sweep_file;  ///< path the sweep was read from (may be empty)
  ManifestCounts runs;
  int threads = 0;
  std::uint64_t shard_index = 0;
  std::uint64_t shard_count = 1;
  std::string start_utc;  ///< ISO 8601
  std::string end_utc;    ///< empty while running
  double wall_s = 0.0;
  double runs_per_s = 0.0;  ///< runs simulated by this invocation / wall_s
  std::string status;       ///< "running", "complete", "interrupted", "failed"
};

/// 16 hex digits: FNV-1a 64 of the sweep JSON's dump (canonical: keys sorted, no spaces), so
/// reformatting the file does not change it.
[[nodiscard]] std::string sweep_hash(const nlohmann::json& sweep);

/// This build's version: project()'s semantic version, and `git describe` of the checkout it was
/// configured in when it was one, e.g. "0.1.0 (v0.1.0-3-g1a2b3c4-dirty)".
[[nodiscard]] std::string fsweep_version();

/// What `fsweep --version` prints: "fsweep <fsweep_version()>", the compiler, and the versions of
/// oneTBB, nlohmann_json and OMPL, one a line.
[[nodiscard]] std::string version_text();

/// The current time, UTC, ISO 8601 with seconds: "2024-05-01T12:34:56Z".
[[nodiscard]] std::string utc_now_iso8601();

/// The manifest's JSON: sweep (the file's JSON), sweep_file, sweep_hash, name, objective, seed,
/// repetitions, warnings (sweep_warnings(): what the CLI printed), maps [{label, source,
/// content_hash}] (each map as loaded; run keys cover the hash), skipped_maps [{where, file,
/// reason}] (dataset plans left out by "on_bad_map": "skip"), runs {total, done, skipped,
/// ran, failed}, shard {index, count}, git_revision, fsweep_version, compiler, libraries {oneTBB,
/// nlohmann_json, OMPL}, host,
/// cpu_model, threads, start_utc, end_utc (null while running), wall_s, runs_per_s, status.
[[nodiscard]] nlohmann::json manifest_json(const SweepPlan& plan, const ManifestInfo& info);

/// Writes `manifest` to `path` (temp file and rename: never torn).
void write_manifest(const std::string& path, const nlohmann::json& manifest);

/// The manifest at `path`; nullopt when the file is missing, unreadable or has no sweep_hash.
[[nodiscard]] std::optional<nlohmann::json> read_manifest(const std::string& path);

/// How the maps `manifest` records ("maps": label, source, content_hash, in plan order) differ
/// from `plan`'s: one line per changed, added or removed map (a dataset plan that now loads or
/// no longer does), or one line when the manifest records none. Empty when they agree.
[[nodiscard]] std::vector<std::string> changed_maps(const nlohmann::json& manifest, const SweepPlan& plan);

/// The sweep_hash of the manifest at `path`; nullopt when the file is missing or unreadable.
[[nodiscard]] std::optional<std::string> read_manifest_hash(const std::string& path);

}  // namespace sweep
}  // namespace fsweep
