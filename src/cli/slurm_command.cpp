/// @file slurm_command.cpp
/// `fsweep slurm SWEEP.json --tasks N`: validates the sweep, writes an sbatch job array (one
/// shard per array task, several when N exceeds the cluster's MaxArraySize) and a merge job to
/// <out>/slurm/ (slurm_script.hpp), and submits both when sbatch is on PATH (the merge with
/// --dependency=afterany on the array), else (or with --dry-run) prints them and the sbatch
/// commands. Exit 0 written (and submitted), 1 when the array was submitted but the merge job
/// was not, 2 on bad input or a failed array submission.

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "cli/output_dir.hpp"
#include "cli/sweep_warnings.hpp"
#include "core/config_error.hpp"
#include "core/files.hpp"
#include "sweep/slurm_script.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/weight_search_runner.hpp"

namespace fsweep::cli {
namespace {

namespace fs = std::filesystem;

struct SlurmCommandOptions {
  std::string sweep_file;
  std::vector<std::string> overrides;
  std::uint64_t tasks = 0;
  std::string partition;
  std::string time;
  int cpus = 1;
  std::string mem;
  std::string account;
  std::string qos;
  std::string gres;
  std::vector<std::string> sbatch_lines;
  std::vector<std::string> setup_lines;
  std::string out;
  std::uint64_t max_array_size = 0;
  bool max_array_size_given = false;
  bool dry_run = false;
  std::string fsweep;
};

/// The executable `name` on PATH, or nullopt.
std::optional<std::string> find_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return std::nullopt;
  std::string_view rest(path);
  while (true) {
    const auto colon = rest.find(':');
    const std::string dir(rest.substr(0, colon));
    const std::string candidate = (dir.empty() ? std::string(".") : dir) + "/" + name;
    if (::access(candidate.c_str(), X_OK) == 0 && fs::is_regular_file(candidate)) return candidate;
    if (colon == std::string_view::npos) return std::nullopt;
    rest.remove_prefix(colon + 1);
  }
}

struct Captured {
  int status = -1;  ///< exit status, -1 when the command could not run or was killed
  std::string out;  ///< its stdout (stderr goes to ours unless the command redirects it)
};

Captured capture(const std::string& command) {
  Captured c;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return c;
  char buf[4096];
  std::size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof(buf), pipe)) > 0) c.out.append(buf, n);
  const int raw = ::pclose(pipe);
  c.status = (raw != -1 && WIFEXITED(raw)) ? WEXITSTATUS(raw) : -1;
  return c;
}

/// The absolute, lexically normal form of `p` without a trailing slash.
std::string absolute_path(const std::string& p) {
  std::string s = fs::absolute(p).lexically_normal().string();
  while (s.size() > 1 && s.back() == '/') s.pop_back();
  return s;
}

void write_script(const std::string& path, const std::string& text) {
  write_file_atomically(path, text);  // IoError naming the file and the OS error
  ::chmod(path.c_str(), 0755);        // convenient to run by hand; sbatch does not need it
}

/// "3" or "2 to 3": runs per shard of an N-way split of `runs` runs.
std::string runs_per_shard(std::uint64_t runs, std::uint64_t shards) {
  const std::uint64_t lo = runs / shards;
  const std::uint64_t hi = lo + (runs % shards != 0 ? 1 : 0);
  return lo == hi ? std::to_string(lo) : std::to_string(lo) + " to " + std::to_string(hi);
}

/// The merge submission as a shell line taking the array job id from $array_id, for users who
/// submit by hand. Built from slurm_merge_submit_command() so both agree; the id goes in as a
/// marker word and is swapped for the variable after quoting (shell_quote would single-quote
/// a `$`, and the shell would then not expand it).
std::string merge_command_line(const std::string& out_dir) {
  constexpr std::string_view kJobIdMarker = "ARRAYJOBID";
  std::string line = shell_command(slurm_merge_submit_command(out_dir, std::string(kJobIdMarker)));
  line.replace(line.find(kJobIdMarker), kJobIdMarker.size(), "\"$array_id\"");
  return line;
}

/// The scripts' options: the command's, with absolute paths, and the executable checked.
SlurmScriptOptions script_options(const SlurmCommandOptions& o, const SweepPlan& plan) {
  SlurmScriptOptions s;
  s.sweep_file = absolute_path(o.sweep_file);
  s.overrides = o.overrides;
  s.out_dir = absolute_path(o.out.empty() ? plan.output_dir() : o.out);
  check_output_dir(s.out_dir, OutputKind::Sweep, "--out");  // the jobs run and merge the sweep there
  s.work_dir = absolute_path(fs::current_path().string());
  s.name = plan.name();
  s.shards = o.tasks;
  s.cpus = o.cpus;
  s.partition = o.partition;
  s.time = o.time;
  s.mem = o.mem;
  s.account = o.account;
  s.qos = o.qos;
  s.gres = o.gres;
  s.sbatch_lines = o.sbatch_lines;
  s.setup_lines = o.setup_lines;
  s.fsweep = absolute_path(o.fsweep.empty() ? fs::read_symlink("/proc/self/exe").string() : o.fsweep);
  if (::access(s.fsweep.c_str(), X_OK) != 0 || !fs::is_regular_file(s.fsweep)) {
    throw ConfigError("--fsweep", "'" + s.fsweep + "' is not an executable file");
  }
  return s;
}

/// MaxArraySize: the cluster's (scontrol), capped by --max-array-size, else Slurm's default;
/// returns where it came from.
std::string choose_max_array_size(const SlurmCommandOptions& o, SlurmScriptOptions& s) {
  std::optional<std::uint64_t> cluster_k;
  if (find_on_path("scontrol"))
    cluster_k = parse_max_array_size(capture("scontrol show config 2>/dev/null").out);
  if (cluster_k && (!o.max_array_size_given || *cluster_k <= o.max_array_size)) {
    s.max_array_size = *cluster_k;
    return "from scontrol show config";
  }
  if (o.max_array_size_given) {
    s.max_array_size = o.max_array_size;
    return "from --max-array-size";
  }
  s.max_array_size = kDefaultMaxArraySize;
  return "Slurm's default; no scontrol answered";
}

/// What was written: runs per shard, array tasks, the scripts' paths.
void print_plan(const SweepPlan& plan, const SlurmScriptOptions& s, std::uint64_t tasks,
                const std::string& k_source) {
  const std::uint64_t runs = plan.run_count();
  std::cout << "sweep " << plan.name() << ": " << runs << " runs (" << plan.configuration_count()
            << " configurations x " << plan.repetitions() << " repetitions) in " << s.shards << " shards of "
            << runs_per_shard(runs, s.shards) << " runs\n";
  const std::vector<std::pair<std::uint64_t, std::uint64_t>> searches = weight_search_blocks(plan);
  if (s.shards > runs && (runs > 0 || searches.empty())) {
    std::cout << "note: more shards than runs; shards " << runs << ".." << s.shards - 1 << " have no runs\n";
  }
  for (std::size_t id = 0; id < searches.size(); ++id) {
    const auto [vectors, blocks] = searches[id];
    std::cout << "exact weight search " << id << ": " << vectors << " weight vectors in " << blocks
              << " blocks of 8^4, divided among the shards by block\n";
    if (s.shards > blocks) {
      const std::uint64_t idle = s.shards - blocks;
      std::cout << "note: more shards than search " << id << "'s blocks: " << idle
                << (idle == 1 ? " shard has" : " shards have") << " none of it (at most " << blocks
                << " are useful)\n";
    }
  }
  std::cout << "array: " << tasks << " tasks (MaxArraySize " << s.max_array_size << ", " << k_source << ")";
  if (tasks < s.shards) {
    std::cout << "; packed: task t runs shards t, t+" << tasks << ", t+" << 2 * tasks << ", ... below "
              << s.shards << " one after the other (" << runs_per_shard(s.shards, tasks)
              << " shards per task)";
  } else {
    std::cout << ", one shard each";
  }
  std::cout << "\nwrote " << slurm_array_script_path(s.out_dir) << " and "
            << slurm_merge_script_path(s.out_dir) << "; job logs go to " << slurm_log_dir(s.out_dir) << "/\n";
}

/// Submits the array, then the merge depending on it. Exit status 1 when the merge could not
/// be submitted (the array was).
int submit(const SlurmScriptOptions& s) {
  const Captured a = capture(shell_command(slurm_array_submit_command(s.out_dir)));
  const auto array_id = parse_sbatch_job_id(a.out);
  if (a.status != 0 || !array_id) {
    throw std::runtime_error("sbatch failed to submit the array (exit " + std::to_string(a.status) +
                             ", output '" + a.out + "'); the scripts are in " + slurm_dir(s.out_dir));
  }
  std::cout << "submitted array job " << *array_id << '\n';
  const auto merge_cmd = slurm_merge_submit_command(s.out_dir, *array_id);
  const Captured m = capture(shell_command(merge_cmd));
  const auto merge_id = parse_sbatch_job_id(m.out);
  if (m.status != 0 || !merge_id) {
    std::cerr << "fsweep slurm: sbatch failed to submit the merge job (exit " << m.status << ", output '"
              << m.out << "'); submit it yourself:\n  " << shell_command(merge_cmd) << '\n';
    return 1;
  }
  std::cout << "submitted merge job " << *merge_id << " (starts when every array task has ended)\n"
            << "watch: squeue -j " << *array_id << "," << *merge_id << "   (afterwards: sacct -j "
            << *array_id << ")\n"
            << "results: " << s.out_dir << "/ (runs.csv, summary.csv, best.csv once the merge job is done; "
            << "its log: " << slurm_log_dir(s.out_dir) << "/merge_" << *merge_id << ".out)\n";
  return 0;
}

int run_slurm(const SlurmCommandOptions& o) {
  if (o.tasks == 0) throw ConfigError("--tasks", "must be >= 1 (the number of shards), got 0");
  if (o.cpus < 1) throw ConfigError("--cpus", "must be >= 1, got " + std::to_string(o.cpus));
  if (o.max_array_size_given && o.max_array_size == 0)
    throw ConfigError("--max-array-size", "must be >= 1, got 0");

  // 1. The sweep: loaded and expanded here, so that its errors show now and not on the cluster.
  const SweepPlan plan = SweepPlan::from_file(o.sweep_file, o.overrides);
  print_sweep_warnings(plan, o.sweep_file);
  SlurmScriptOptions s = script_options(o, plan);

  // 2. The scripts.
  const std::string k_source = choose_max_array_size(o, s);
  const std::uint64_t tasks = slurm_array_tasks(s.shards, s.max_array_size);
  const std::string array_script = render_slurm_array_script(s);
  const std::string merge_script = render_slurm_merge_script(s);
  create_output_dir(slurm_log_dir(s.out_dir));
  write_script(slurm_array_script_path(s.out_dir), array_script);
  write_script(slurm_merge_script_path(s.out_dir), merge_script);
  print_plan(plan, s, tasks, k_source);
  if (o.dry_run || !find_on_path("sbatch").has_value()) {
    std::cout << (o.dry_run ? "dry run" : "sbatch is not on PATH") << ": not submitted. The scripts:\n\n"
              << "==> " << slurm_array_script_path(s.out_dir) << " <==\n"
              << array_script << "\n==> " << slurm_merge_script_path(s.out_dir) << " <==\n"
              << merge_script << "\nTo submit:\n"
              << "  array_id=$(" << shell_command(slurm_array_submit_command(s.out_dir)) << ")\n"
              << "  " << merge_command_line(s.out_dir) << '\n';
    return 0;
  }
  // 3. Submission.
  return submit(s);
}

}  // namespace

Command add_slurm_command(CLI::App& app) {
  auto o = std::make_shared<SlurmCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "slurm",
      "Run a sweep on a Slurm cluster: write <out>/slurm/array.sbatch (a job array, one shard per task) and "
      "merge.sbatch (fsweep merge, submitted with --dependency=afterany on the array so that it runs even "
      "when "
      "some tasks failed and then lists the missing runs), and submit both when sbatch is on PATH. Failed "
      "shards: "
      "sbatch --array=<their task ids> <out>/slurm/array.sbatch (shards resume), then fsweep merge <out>");
  add_sweep_positionals(*sub, o->sweep_file, o->overrides, " (the jobs run with them)");
  sub->add_option("--tasks", o->tasks, "Number of shards N (fsweep run --shard i/N for i = 0..N-1)")
      ->required();
  sub->add_option("--partition", o->partition, "Slurm partition (default: the cluster's)");
  sub->add_option("--time", o->time,
                  "Time limit per array task, Slurm format (e.g. 2:00:00; default: the partition's)");
  sub->add_option("--cpus", o->cpus, "CPUs per array task; each shard runs with that many threads")
      ->capture_default_str();
  sub->add_option("--mem", o->mem, "Memory per array task, Slurm format (e.g. 4G; default: the partition's)");
  sub->add_option("--account", o->account, "Slurm account both jobs are charged to (letters, digits, _ . -)");
  sub->add_option("--qos", o->qos, "Slurm quality of service of both jobs (letters, digits, _ . -)");
  sub->add_option("--gres", o->gres, "Generic resources per array task, Slurm format (e.g. gpu:1)");
  sub->add_option("--sbatch", o->sbatch_lines,
                  "Another #SBATCH directive of both jobs (repeatable, in order): --option or --option=value "
                  "as for sbatch, e.g. --sbatch --constraint=a100 (a leading '#SBATCH ' is dropped); not one "
                  "of the directives fsweep slurm writes itself")
      ->allow_extra_args(false);  // one value per --sbatch: `--sbatch --exclusive sweep.json` keeps the sweep
  sub->add_option(
         "--setup", o->setup_lines,
         "A shell line both jobs run before fsweep, in the directory fsweep slurm ran in (repeatable, "
         "in order), e.g. --setup 'module load gcc/12'")
      ->allow_extra_args(false);
  sub->add_option("--out", o->out, "Output directory (default: the sweep's output.dir or results/<name>)");
  sub->add_option(
      "--max-array-size", o->max_array_size,
      "Largest job array to submit (indices 0..K-1); the cluster's MaxArraySize from scontrol caps it; "
      "default 1001 when scontrol does not answer. Shards beyond it are packed into the tasks");
  sub->add_flag("--dry-run", o->dry_run,
                "Write and print the scripts and the sbatch commands; submit nothing");
  sub->add_option("--fsweep", o->fsweep, "fsweep executable the jobs run (default: this one)");
  CLI::Option* k = sub->get_option("--max-array-size");
  return [o, k] {
    o->max_array_size_given = k->count() > 0;
    return run_slurm(*o);
  };
}

}  // namespace fsweep::cli
