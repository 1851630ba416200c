#pragma once
/// @file optimum_table.hpp
/// The offline optimum of a sweep's competitive maps (sweep_plan.hpp, `competitive`): certified
/// bounds from optimum/optimum.hpp per (map instance, robot), computed once before the runs and
/// kept in the output directory's `optima.csv`, and the runs.csv cells they give
/// (runs_schema.hpp's kCompetitiveColumns; docs/results.md).
///
/// Key: the map instance's content_hash() (size, resolution, start and cells: a random start is
/// part of it), the robot's resolved JSON (to_json(RobotParams), the dock resolved to the map's
/// start, without the sensor's miss_probability, which the noiseless offline robot ignores) and
/// optimum_solver_version() (the solver's options; a change recomputes). The solver runs with the library's
/// deterministic budgets and never a deadline, one key per thread, so a value is a pure function of its key:
/// a resumed sweep, the shards of a sharded sweep and an unsharded run write the same cells for any thread
/// count, whether a value was computed or read from the cache (numbers are written as the shortest text that
/// reads back to the same double).
///
/// optima.csv: `solver,map_hash,robot,lower_m,upper_m,exact,error` plus informative columns
/// (targets, nodes, lower_method, upper_method, exact_expansions, time_s), one row per key, sorted
/// by key; rewritten whole (temp file and rename) after each computed key, so a kill keeps what
/// was computed. A file that does not read (another layout, a torn record) is set aside with a
/// warning and recomputed.

#include <cstdint>
#include <limits>
#include <map>
#include <string>

#include "sim/run_result.hpp"
#include "sim/run_spec.hpp"
#include "sweep/sweep_plan.hpp"

namespace fsweep {
inline namespace sweep {

/// The cache file in an output directory (a shard's directory for a shard).
inline constexpr char kOptimaFile[] = "optima.csv";

/// The solver and its options, as optima.csv keys record them.
[[nodiscard]] std::string optimum_solver_version();

/// The bounds of one key.
struct OptimumBounds {
  /// Certified bounds in metres: +infinity when none (no route the replay accepts; for lower, no
  /// route can exist); NaN with an error.
  double lower_m = std::numeric_limits<double>::quiet_NaN();
  double upper_m = std::numeric_limits<double>::quiet_NaN();
  bool exact = false;
  /// The solver refused the instance (its ConfigError's message: the beam model, a map above the
  /// size limit, ...); empty otherwise.
  std::string error;
  /// Informative (optima.csv only).
  int targets = 0;
  int nodes = 0;
  std::string lower_method;
  std::string upper_method;
  long exact_expansions = 0;
  double time_s = 0.0;
};

/// The key of `spec`'s map instance and robot (file comment), without the solver version.
[[nodiscard]] std::string optimum_key(const RunSpec& spec);

/// solve_optimum() of `spec` with the library's default (deterministic) options; a ConfigError
/// becomes `error`.
[[nodiscard]] OptimumBounds compute_optimum(const RunSpec& spec);

/// What prepare_optima() did.
struct OptimumReport {
  std::size_t needed = 0;    ///< keys of the shard's runs on competitive maps
  std::size_t cached = 0;    ///< of those, read from optima.csv
  std::size_t computed = 0;  ///< of those, computed now
  double seconds = 0.0;      ///< wall time of the computations
};

/// The bounds of a sweep's keys, read-only once prepared (safe to share between threads).
class OptimumTable {
 public:
  /// The bounds of `spec`'s key, or nullptr when it was not prepared.
  [[nodiscard]] const OptimumBounds* find(const RunSpec& spec) const;
  [[nodiscard]] std::size_t size() const { return entries_.size(); }

  /// Reads `<dir>/optima.csv` (entries of this solver version), computes the keys the runs of
  /// shard `shard_index` of `shard_count` on competitive maps need that it lacks (`threads` at
  /// a time, each solve single-threaded) and rewrites the file. Nothing is read or written when
  /// no map of `plan` is competitive.
  static OptimumTable prepare(const SweepPlan& plan, const std::string& dir, std::uint64_t shard_index,
                              std::uint64_t shard_count, int threads, OptimumReport& report);

 private:
  std::map<std::string, OptimumBounds> entries_;  ///< by optimum_key()
};

/// Writes `<dir>/optima.csv` with the entries of this solver version found in the shards'
/// optima.csv files (any shard's entry of a key: the solver is deterministic), when any shard has
/// the file. Returns the entries written.
std::size_t merge_optima(const std::string& dir, const std::vector<std::string>& shard_dirs);

/// The kCompetitiveColumns cells of a run of `map` (in that order): empty with the note "map not
/// competitive" for a map that is not; else the bounds (`optimum` null: the run failed before
/// any was known) and, for a run that ended complete with completeness 1 (`result`; null: the run
/// threw), distance_to_final_coverage_m over the upper and the lower bound, or a note saying why
/// not.
[[nodiscard]] std::vector<std::string> competitive_cells(const SweepMap& map, const OptimumBounds* optimum,
                                                         const RunResult* result);

}  // namespace sweep
}  // namespace fsweep
