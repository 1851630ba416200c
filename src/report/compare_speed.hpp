#pragma once
/// @file compare_speed.hpp
/// Speed side of `fsweep compare` (compare.hpp, check 4): the manifests' facts, Google
/// Benchmark's bench.json, whether both sides ran on the same machine, and time-ratio checks.

#include <optional>
#include <string>
#include <vector>

#include "report/compare.hpp"

namespace fsweep {
inline namespace report {

/// What compare needs from a manifest.json (manifest.hpp).
struct ManifestFacts {
  std::string path;
  std::optional<std::string> sweep_hash, host, cpu_model, status;
  std::optional<long long> threads;
  /// The sweep's wall time (manifest `wall_s`), seconds.
  std::optional<double> wall_s;
  /// wall_s / runs.ran; nullopt when either is missing or not positive.
  std::optional<double> seconds_per_run;
};

/// Reads `path`. Throws ConfigError naming the file when it is missing, not JSON or not an
/// object; fields of the wrong type count as absent.
[[nodiscard]] ManifestFacts read_manifest_facts(const std::string& path);

/// One micro-benchmark's time: the median aggregate's real_time if the file has one, else the
/// mean real_time of its iteration rows; nanoseconds.
struct BenchTime {
  std::string name;  ///< run_name (name for files without run_name)
  double real_time_ns = 0.0;
  bool error = false;  ///< Google Benchmark reported error_occurred for it
};

/// bench.json (Google Benchmark's JSON output).
struct BenchFile {
  std::string path;
  std::vector<BenchTime> times;  ///< in order of first appearance
  std::optional<std::string> host_name;
  std::optional<double> num_cpus, mhz_per_cpu;
};

/// Reads `path`; nullopt when the file does not exist. Throws ConfigError naming the file (and
/// JSON path) for malformed JSON, a benchmark without name or numeric real_time, or a time_unit
/// other than ns, us, ms, s.
[[nodiscard]] std::optional<BenchFile> read_bench_file(const std::string& path);

/// The machine facts that differ between baseline and NEW ("cpu_model: 'A' (baseline) vs 'B'
/// (new)"): manifest host and cpu_model, bench.json host_name, num_cpus and mhz_per_cpu, each
/// only when both sides have it. Empty = same machine.
[[nodiscard]] std::vector<std::string> machine_differences(const ManifestFacts& baseline,
                                                           const ManifestFacts& current,
                                                           const BenchFile* baseline_bench,
                                                           const BenchFile* current_bench);

/// A time-ratio check (current / baseline): Slower above 1 + tolerance, Faster below
/// 1 / (1 + tolerance), else WithinTolerance; NotJudged when a value is missing or not
/// positive. Slower fails when `may_fail`.
[[nodiscard]] CompareCheck time_ratio_check(std::string kind, std::string name, std::string metric,
                                            std::optional<double> baseline, std::optional<double> current,
                                            double tolerance, bool may_fail);

/// The sweep throughput check and, when both sides have bench.json, one check per baseline
/// benchmark (a benchmark missing in NEW or with an error there is a failure; one only in NEW
/// is listed as New), appended to `report.checks`; warnings for a missing bench.json on one
/// side or different thread counts.
void add_sweep_speed_checks(CompareReport& report, const ManifestFacts& baseline,
                            const ManifestFacts& current, const BenchFile* baseline_bench,
                            const BenchFile* current_bench, const CompareOptions& options);

}  // namespace report
}  // namespace fsweep
