#pragma once
/// @file manifest.hpp
/// manifest.json of a sweep's output directory (layout in sweep_runner.hpp): what was run, on
/// what, by which build, and how it went.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace fsweep {
inline namespace sweep {

class SweepPlan;

/// Run counts of a sweep (or shard) as the manifest reports them.
struct ManifestCounts {
  std::uint64_t total = 0;       ///< runs in the sweep (or shard)
  std::uint64_t done = 0;        ///< runs with a row in runs.csv
  std::uint64_t skipped = 0;     ///< already done when this invocation started
  std::uint64_t ran = 0;         ///< simulated by this invocation
  std::uint64_t failed = 0;      ///< rows in runs.csv whose end_reason is `error`
  std::uint64_t ran_failed = 0;  ///< of the runs this invocation simulated, those that failed
};

/// Everything the manifest records besides the plan and the build: this invocation (a session)
/// and the sessions before it.
struct ManifestInfo {
  std::string sweep_file;  ///< path the sweep was read from (may be empty)
  ManifestCounts runs;
  int threads = 0;
  std::uint64_t shard_index = 0;
  std::uint64_t shard_count = 1;
  std::string start_utc;    ///< ISO 8601
  std::string end_utc;      ///< empty while running
  double wall_s = 0.0;      ///< this invocation, weight searches included
  double runs_per_s = 0.0;  ///< runs simulated by this invocation / the seconds until they were written
  std::string status;       ///< "running", "complete", "interrupted", "failed"
  /// The sessions of the earlier invocations on the directory, oldest first (manifest_sessions()
  /// of its manifest); empty for a new or --fresh directory.
  nlohmann::json sessions = nlohmann::json::array();
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

/// The manifest's JSON: sweep (the file's JSON with the command-line overrides applied: what
/// ran), sweep_file, overrides (SweepPlan::overrides(), as given), sweep_hash (of `sweep`), name,
/// objective, seed,
/// repetitions, warnings (sweep_warnings(): what the CLI printed), maps [{label, source,
/// content_hash}] (each map as loaded; run keys cover the hash), skipped_maps [{where, file,
/// reason}] (dataset plans left out by "on_bad_map": "skip"), runs {total, done, skipped,
/// ran, failed}, shard {index, count}, git_revision, fsweep_version, compiler, libraries {oneTBB,
/// nlohmann_json, OMPL}, host, cpu_model, threads, start_utc, end_utc (null while running),
/// wall_s, runs_per_s, status, sessions.
///
/// `sessions` is `info.sessions` and then this invocation's session_json(). The top-level fields
/// describe the directory over all its sessions: status, sweep_file, threads, end_utc and
/// runs.skipped are this (the last) session's; start_utc is the first session's; wall_s and
/// runs.ran are summed over the sessions; runs_per_s is the runs simulated over all sessions per
/// second spent simulating them (sessions that simulated nothing do not count), 0 when none did;
/// runs.total, done and failed are the state of the files.
[[nodiscard]] nlohmann::json manifest_json(const SweepPlan& plan, const ManifestInfo& info);

/// One session's entry of a manifest's `sessions`: start_utc, end_utc (null while running),
/// status, sweep_hash, sweep_file, fsweep_version, git_revision, host, threads, shard {index,
/// count}, runs {ran, skipped, failed} (simulated in it, already done when it started, of
/// those simulated the failed ones), wall_s, runs_per_s.
[[nodiscard]] nlohmann::json session_json(const SweepPlan& plan, const ManifestInfo& info);

/// The sessions `manifest` records (its `sessions`, the objects among them), oldest first. A
/// manifest of an fsweep that kept no sessions gives one, made of its top-level fields.
[[nodiscard]] nlohmann::json manifest_sessions(const nlohmann::json& manifest);

/// Runs simulated per second over `sessions` (manifest_sessions()): their runs.ran summed, over
/// the seconds those that simulated runs spent on them (runs.ran / runs_per_s each); 0 when none did.
[[nodiscard]] double sessions_runs_per_s(const nlohmann::json& sessions);

/// Writes `manifest` to `path` (temp file and rename: never torn).
void write_manifest(const std::string& path, const nlohmann::json& manifest);

/// Records that the session failed: `manifest` (its status "failed") written as write_manifest()
/// does; when the machine refuses that write too (the full disk or the file size limit that
/// stopped the session), the manifest already at `path` has its top-level status changed from
/// "running" to "failed" in place, the same number of bytes (`"failed" `), so no space is needed.
/// Never throws: it runs while another error is reported, and that one is the one to report.
void record_failed_manifest(const std::string& path, const nlohmann::json& manifest) noexcept;

/// Two versions of a sweep file (the manifests' "sweep") that differ in their "description"
/// alone: the same runs and searches. A results directory resumes as it is (its manifest takes
/// the new hash), and shards run before and after the change merge.
[[nodiscard]] bool same_sweep_but_description(nlohmann::json before, nlohmann::json now);

/// The manifest at `path`; nullopt when the file is missing, unreadable or has no sweep_hash.
[[nodiscard]] std::optional<nlohmann::json> read_manifest(const std::string& path);

/// How the maps `manifest` records ("maps": label, source, content_hash, in plan order) differ
/// from `plan`'s: one line per changed, added or removed map (a dataset plan that now loads or
/// no longer does), or one line when the manifest records none. Empty when they agree.
[[nodiscard]] std::vector<std::string> changed_maps(const nlohmann::json& manifest, const SweepPlan& plan);

/// The maps `manifest` records (label, source, content_hash) whose content differs from the map
/// of `plan` with the same label and source, wherever it is in the plan (maps may be added to or
/// moved in an extended sweep, sweep_runner.hpp), one line each; or one line when the manifest
/// records none. Empty when they agree.
[[nodiscard]] std::vector<std::string> changed_map_contents(const nlohmann::json& manifest,
                                                            const SweepPlan& plan);

/// The sweep_hash of the manifest at `path`; nullopt when the file is missing or unreadable.
[[nodiscard]] std::optional<std::string> read_manifest_hash(const std::string& path);

}  // namespace sweep
}  // namespace fsweep
