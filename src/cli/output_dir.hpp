#pragma once
/// @file output_dir.hpp
/// The output directory of a subcommand, and what an existing one holds: a command writes only
/// into a new directory or one holding its own kind of output, never over another command's files.

#include <optional>
#include <string>

namespace fsweep {

/// The kinds of output directory the commands write, each recognised by the files that only it
/// writes (or, for a sweep, a manifest.json with a sweep_hash).
enum class OutputKind {
  Sweep,        ///< `fsweep run` / `merge`: runs.csv, manifest.json (with a sweep_hash), progress.csv, ...
  Sim,          ///< `fsweep sim`: run.csv, progress.csv, trajectory.png
  PlanBench,    ///< `fsweep plan-bench --out`: queries.csv, summary.csv, ompl_benchmark.log
  PlanCompare,  ///< `fsweep plan-compare --out`: pairs.csv, summary.csv, manifest.json
  Compare,      ///< `fsweep compare --out`: compare.csv, compare.html
  Plots,        ///< `fsweep plot --out`: progress.png, metrics.png, heat maps
  Paired,       ///< `fsweep paired --out`: paired.csv, paired.json
  Optimum,      ///< `fsweep optimum --out`: optimum.csv, route.png
};

/// A directory holding `shard-<i>-of-<n>` folders (a sharded sweep's --out) and no other
/// command's files is a Sweep's.

/// What an existing directory holds: its kind and, for messages, e.g. "the results of sweep
/// 'default' (manifest.json, runs.csv)" (the files found that show the kind).
struct OutputDirContents {
  OutputKind kind = OutputKind::Sweep;
  std::string description;
};

/// The kind of output `dir` holds; nullopt when it does not exist, is not a directory or holds
/// none of the files that mark a kind (an empty or unrelated directory).
[[nodiscard]] std::optional<OutputDirContents> output_dir_contents(const std::string& dir);

/// Throws ConfigError naming `dir` and what it holds when it holds the output of another kind
/// than `kind` ("choose another `option`"); a new directory or one of `kind` passes.
void check_output_dir(const std::string& dir, OutputKind kind, const std::string& option);

/// Creates `dir` and its parents (nothing to do when it exists). Throws ConfigError naming
/// `dir` and the system's reason when it cannot be created (e.g. a file of that name exists).
void create_output_dir(const std::string& dir);

/// check_output_dir(), then create_output_dir().
void create_output_dir(const std::string& dir, OutputKind kind, const std::string& option);

}  // namespace fsweep
