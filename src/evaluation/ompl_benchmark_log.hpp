#pragma once
/// @file ompl_benchmark_log.hpp
/// A plan benchmark (plan_bench.hpp) as OMPL's benchmark log: the format of OMPL's
/// ompl::tools::Benchmark, whose EBNF is in OMPL's documentation ("How to Benchmark Planners",
/// "The benchmark logfile format"). OMPL's `ompl_benchmark_statistics` script turns such logs
/// into the SQLite database that Planner Arena (plannerarena.org) and OMPL's own plots read:
/// one `experiments` row per log, one `plannerConfigs` row per planner and its settings, one
/// `runs` row per planner and query, `progress` rows per run where a planner reports progress.
///
/// What the log holds (`fsweep plan-bench --out DIR` writes DIR/ompl_benchmark.log):
/// - Preamble: "OMPL version V", "Experiment NAME", the experiment properties (numbers, e.g.
///   "map_width INTEGER = 65"), "Running on HOST", "Starting at DATE", the setup and cpuinfo
///   blocks, "SEED is the random seed", "T seconds per run" (the time limit),
///   "0 MB per run" (no memory limit: none is set nor measured), "N runs per planner" (the
///   queries), "S seconds spent to collect the data", one enum (`plan_status`: PlanStatus's
///   names in order, so a value is the status's number), "K planners".
/// - Per planner: its name (the registry name, e.g. "ompl:RRTstar"), its resolved parameters
///   as common properties ("time_limit_s = 0.5"), then one row per query in query order with
///   the run properties of kBenchRunProperties; the values are those of queries.csv. A query the
///   planner did not solve has no solution length, length ratio, energy or turns (empty, NULL in
///   the database; queries.csv writes 0 there).
/// - Per planner whose runs sampled progress properties (PlanProgress): "time REAL" and the
///   planner's properties, then one line per query with its samples ("time,value,...,;").

#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "evaluation/plan_bench.hpp"

namespace fsweep {
inline namespace evaluation {

/// A numeric experiment property: becomes a column of the `experiments` table (Planner Arena's
/// "problem parameters").
struct LogProperty {
  /// One word (the script would drop spaces), e.g. "map_width".
  std::string name;
  /// "INTEGER", "REAL" or "BOOLEAN".
  std::string type;
  /// The value as text, a number.
  std::string value;
};

/// The preamble of a benchmark log.
struct BenchmarkLogExperiment {
  /// Experiment name; written as one word (whitespace becomes '_'; the script reads the last
  /// word of the line).
  std::string name;
  /// The OMPL version of the build (ompl_version()).
  std::string ompl_version;
  /// The host (one word, like the name).
  std::string host;
  /// When the benchmark started, e.g. "2025-01-02T03:04:05Z".
  std::string date;
  /// What was benchmarked: the setup block, one or more lines.
  std::string setup;
  /// The machine's processor: the cpuinfo block, one or more lines.
  std::string cpuinfo;
  std::uint64_t seed = 0;
  /// Time limit per run (s): the largest of the planners' limits, +infinity when one has none.
  double time_limit_s = 0.0;
  /// Seconds spent planning every query with every planner.
  double total_time_s = 0.0;
  std::vector<LogProperty> properties;
};

/// A planner of the log: its name and resolved parameters (the registry's JSON).
struct BenchmarkLogPlanner {
  std::string name;
  nlohmann::json params;
};

/// The run properties of every planner, in the order of a row (OMPL's names where they mean
/// the same: time, solved, solution length; the database turns spaces into underscores).
inline constexpr std::array<std::string_view, 13> kBenchRunProperties{
    "time REAL",             // the query's wall time (s), queries.csv's time_s
    "solved BOOLEAN",        // status Success
    "plan_status ENUM",      // the PlanStatus, a value of the plan_status enum
    "solution length REAL",  // path length in cells (length_ratio x optimal_cells)
    "length ratio REAL",     // queries.csv's length_ratio
    "energy REAL",           // queries.csv's energy
    "turns INTEGER",         // queries.csv's turns
    "query INTEGER",         // the query's row in queries.csv (from 0)
    "start x INTEGER",
    "start y INTEGER",
    "goal x INTEGER",
    "goal y INTEGER",
    "optimal length REAL",  // queries.csv's optimal_cells
};

/// The name of the enum of plan statuses and of the run property that holds them.
inline constexpr std::string_view kPlanStatusEnum = "plan_status";

/// The experiment name of a plan benchmark: the map SPEC's last path component, '+', then the
/// scenario's file name, or "pairs=N,seed=S" for random pairs; e.g. "den312d.map+den312d.map.scen".
[[nodiscard]] std::string plan_bench_experiment_name(const std::string& map_spec, const std::string& scen,
                                                     int pairs, std::uint64_t seed);

/// The log of a plan benchmark: `plans` [planner][query] as run_plan_bench() returns them for
/// `queries` and `planners`. Throws std::invalid_argument if the sizes disagree, a planner name
/// is empty or holds a line break, or a progress value holds a separator (',', ';', whitespace).
[[nodiscard]] std::string ompl_benchmark_log(const BenchmarkLogExperiment& experiment,
                                             const std::vector<BenchQuery>& queries,
                                             const std::vector<BenchmarkLogPlanner>& planners,
                                             const std::vector<std::vector<BenchPlan>>& plans);

}  // namespace evaluation
}  // namespace fsweep
