#pragma once
/// @file slurm_script.hpp
/// The scripts of `fsweep slurm` (docs/dev/architecture.md, "Sweeps, keys, shards and the weight search",
/// issue 8): an sbatch job array whose tasks run the shards of a sweep (`fsweep run SWEEP --shard i/N`,
/// sweep_runner.hpp) and a merge job
/// (`fsweep merge OUT`, merge.hpp) submitted with an `afterany` dependency on the array. Pure
/// functions of their options, so they are tested without Slurm; the command line
/// (src/cli/slurm_command.cpp) finds the values, writes the files and calls sbatch.
///
/// Packing: a cluster accepts array indices 0..K-1 only (Slurm's MaxArraySize = K). With N
/// shards the array has T = min(N, K) tasks and task t runs shards t, t + T, t + 2T, ... < N
/// one after the other, so every shard is in exactly one task. A task derives its shards from
/// SLURM_ARRAY_TASK_ID alone, so the script can be resubmitted for a subset of the tasks
/// (`sbatch --array=3,7 array.sbatch`) to redo just those shards; each shard resumes where it
/// stopped.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace fsweep {
inline namespace sweep {

/// Slurm's default MaxArraySize (array indices 0..1000).
inline constexpr std::uint64_t kDefaultMaxArraySize = 1001;

/// What the scripts run and the resources they request.
struct SlurmScriptOptions {
  /// Absolute paths: the fsweep executable, the sweep file, the sweep's output directory
  /// (shards go to <out_dir>/shard-i-of-N/) and the directory the jobs run in (where relative
  /// paths of the sweep file that are not beside it are looked for). Not absolute: ConfigError. The output
  /// directory must not contain whitespace, quotes or backslashes (it is written into
  /// `#SBATCH --output=` lines); the others are shell-quoted.
  std::string fsweep;
  std::string sweep_file;
  std::string out_dir;
  std::string work_dir;
  /// The sweep's command-line overrides ("PATH=VALUE", sweep_json_reader.hpp), passed to every
  /// shard's `fsweep run` after the sweep file, each shell-quoted.
  std::vector<std::string> overrides;
  /// The sweep's name ([A-Za-z0-9_.-]+ as sweep_plan.hpp requires); jobs are named
  /// `fsweep-<name>` and `fsweep-<name>-merge`.
  std::string name;
  /// N, the number of shards, >= 1 (else ConfigError).
  std::uint64_t shards = 1;
  /// K, the largest array size the cluster accepts (indices 0..K-1), >= 1 (else ConfigError).
  std::uint64_t max_array_size = kDefaultMaxArraySize;
  /// CPUs per array task (`--cpus-per-task`, >= 1 else ConfigError); each shard runs with
  /// `--threads ${SLURM_CPUS_PER_TASK:-1}`.
  int cpus = 1;
  /// `--partition`, `--time`, `--mem` of both jobs; a directive is written only when its
  /// value is non-empty. Whitespace, quotes, backslashes or NUL in them: ConfigError.
  std::string partition;
  std::string time;
  std::string mem;
  /// `--account` and `--qos` of both jobs, written only when non-empty: names of
  /// [A-Za-z0-9_.-] (else ConfigError).
  std::string account;
  std::string qos;
  /// `--gres` of the array tasks only (e.g. `gpu:1`; the merge job runs `fsweep merge` on one
  /// CPU), written only when non-empty; checked as partition.
  std::string gres;
  /// Further directives of both jobs, in order, each written as `#SBATCH LINE` after fsweep's
  /// own: `--option` or `--option=value` as on sbatch's command line (a leading `#SBATCH ` is
  /// dropped). The option is lower-case letters, digits and '-'; the value as partition. An
  /// option fsweep writes itself (job-name, array, cpus-per-task, output, partition, time, mem,
  /// account, qos, gres), or an abbreviation of one (sbatch takes `--part` for `--partition`):
  /// ConfigError naming the option to use instead.
  std::vector<std::string> sbatch_lines;
  /// Shell lines both jobs run in order, after changing to work_dir and before fsweep (e.g.
  /// `module load gcc/12`, `source venv/bin/activate`), written as given with `set -u` off. A
  /// failing line does not stop the job (add `|| exit 1` to make it). A newline, carriage
  /// return or NUL in one: ConfigError.
  std::vector<std::string> setup_lines;
};

/// T = min(shards, max_array_size): the number of array tasks (indices 0..T-1). Both must be
/// >= 1, else ConfigError.
[[nodiscard]] std::uint64_t slurm_array_tasks(std::uint64_t shards, std::uint64_t max_array_size);

/// The shards array task `task` runs, ascending: task, task + T, task + 2T, ... < shards, with
/// T = slurm_array_tasks(shards, max_array_size). Empty when task >= T.
[[nodiscard]] std::vector<std::uint64_t> slurm_task_shards(std::uint64_t task, std::uint64_t shards,
                                                           std::uint64_t max_array_size);

/// <out_dir>/slurm: where the scripts are written.
[[nodiscard]] std::string slurm_dir(const std::string& out_dir);
/// <out_dir>/slurm/logs: the jobs' output files (`%A_%a.out` for array tasks, `merge_%j.out`).
[[nodiscard]] std::string slurm_log_dir(const std::string& out_dir);
/// <out_dir>/slurm/array.sbatch.
[[nodiscard]] std::string slurm_array_script_path(const std::string& out_dir);
/// <out_dir>/slurm/merge.sbatch.
[[nodiscard]] std::string slurm_merge_script_path(const std::string& out_dir);

/// The bash job-array script: `#SBATCH` directives (job name, `--array=0-(T-1)`,
/// `--cpus-per-task`, the optional partition/time/mem/account/qos/gres, `--output` into
/// slurm_log_dir, then the sbatch_lines), then a body that changes to work_dir, runs the
/// setup_lines, runs `fsweep run SWEEP [OVERRIDES] --out OUT --shard i/N --threads
/// ${SLURM_CPUS_PER_TASK:-1} --quiet` for each shard of SLURM_ARRAY_TASK_ID (all of them even
/// when one fails) and exits 1 if any failed, 0 otherwise; 2 when SLURM_ARRAY_TASK_ID is unset
/// or not below T. Throws ConfigError for bad options (see SlurmScriptOptions).
[[nodiscard]] std::string render_slurm_array_script(const SlurmScriptOptions& o);

/// The bash merge script: `#SBATCH` directives (job name `fsweep-<name>-merge`, one CPU, the
/// optional partition/time/mem/account/qos (no gres), `--output` into slurm_log_dir, then the
/// sbatch_lines), then `cd work_dir`, the setup_lines and `exec fsweep merge OUT` (exit 1 with
/// the missing runs listed when shards are incomplete). Throws ConfigError for bad options.
[[nodiscard]] std::string render_slurm_merge_script(const SlurmScriptOptions& o);

/// argv of the array submission: sbatch --parsable <array script>.
[[nodiscard]] std::vector<std::string> slurm_array_submit_command(const std::string& out_dir);

/// argv of the merge submission: sbatch --parsable --dependency=afterany:<array_job_id>
/// <merge script>. `afterany`: the merge starts when every array task has ended, whether it
/// succeeded or not, so it reports missing runs instead of being cancelled.
[[nodiscard]] std::vector<std::string> slurm_merge_submit_command(const std::string& out_dir,
                                                                  const std::string& array_job_id);

/// `s` as one POSIX shell word: unchanged when it consists only of [A-Za-z0-9_./:=%+,@-] (and
/// is non-empty), else in single quotes with each ' written as '\''.
[[nodiscard]] std::string shell_quote(const std::string& s);

/// argv joined by spaces, each word shell_quote()d: a command line to show or run with sh.
[[nodiscard]] std::string shell_command(const std::vector<std::string>& argv);

/// MaxArraySize from the output of `scontrol show config` (a line `MaxArraySize = 1001`,
/// spaces optional). nullopt when no such line or its value is not a non-negative integer.
[[nodiscard]] std::optional<std::uint64_t> parse_max_array_size(const std::string& scontrol_config);

/// The job id from `sbatch --parsable` output ("1234" or "1234;cluster", surrounding
/// whitespace ignored). nullopt unless the id is a non-empty run of digits.
[[nodiscard]] std::optional<std::string> parse_sbatch_job_id(const std::string& sbatch_output);

}  // namespace sweep
}  // namespace fsweep
