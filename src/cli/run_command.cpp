/// @file run_command.cpp
/// `fsweep run SWEEP.json`: the main job. Prints the run count before starting, progress on
/// stderr, then where the results are. Exit 0 when done, 130 when interrupted (Ctrl-C, SIGTERM;
/// rerun the same command to resume), 2 on configuration errors, 1 when a file cannot be written
/// (a full disk, a file size limit; every file is left whole, and the same command resumes) and
/// when the memory guard stopped an exact weight search (`--max-memory`; its journal is whole, and
/// a rerun with enough memory resumes it).

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "cli/output_dir.hpp"
#include "cli/sweep_warnings.hpp"
#include "core/config_error.hpp"
#include "core/io_error.hpp"
#include "core/memory_limit.hpp"
#include "report/sqlite_export.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_runner.hpp"

namespace fsweep::cli {
namespace {

struct RunCommandOptions {
  std::string sweep_file;
  std::vector<std::string> overrides;
  int threads = 0;
  bool fresh = false;
  std::string out;
  bool quiet = false;
  std::string shard;
  bool sqlite = false;
  std::string max_memory;
};

std::string one_decimal(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.1f", v);
  return buf;
}

/// Reads "i/n" (0 <= i < n).
std::pair<std::uint64_t, std::uint64_t> parse_shard(const std::string& s) {
  const auto slash = s.find('/');
  std::uint64_t i = 0;
  std::uint64_t n = 0;
  const auto read = [](std::string_view part, std::uint64_t& v) {
    const auto [ptr, ec] = std::from_chars(part.data(), part.data() + part.size(), v);
    return ec == std::errc() && ptr == part.data() + part.size() && !part.empty();
  };
  const std::string_view sv(s);
  if (slash == std::string::npos || !read(sv.substr(0, slash), i) || !read(sv.substr(slash + 1), n) ||
      n == 0 || i >= n) {
    throw ConfigError("--shard", "expected i/n with 0 <= i < n (e.g. 3/16), got '" + s + "'");
  }
  return {i, n};
}

/// What a sweep stopped by IoError `os_error` needs before the same command resumes it.
std::string resume_note(int os_error) {
  std::string once = "once the cause is removed";
  switch (os_error) {
    case ENOSPC:
    case EDQUOT:
      once = "once space is freed";
      break;
    case EFBIG:
      once = "once the file size limit is raised";
      break;
    case EROFS:
    case EACCES:
    case EPERM:
      once = "once the directory is writable";
      break;
    default:
      break;
  }
  return "nothing was lost: rerun the same command to resume " + once;
}

int run_command(const RunCommandOptions& o) {
  const SweepPlan plan = SweepPlan::from_file(o.sweep_file, o.overrides);
  // The runner refuses a directory of another sweep (manifest.json's sweep_hash) unless this one
  // only adds runs to it; here one of another command (fsweep sim's progress.csv is not a sweep's).
  const std::string out = o.out.empty() ? plan.output_dir() : o.out;
  check_output_dir(out.empty() ? "." : out, OutputKind::Sweep,
                   o.out.empty() ? "--out (or output.dir)" : "--out");
  print_sweep_warnings(plan, o.sweep_file);
  RunnerOptions options;
  options.threads = o.threads;
  options.fresh = o.fresh;
  options.out_dir = o.out;
  options.sweep_file = o.sweep_file;
  options.progress = !o.quiet;
  if (!o.shard.empty()) std::tie(options.shard_index, options.shard_count) = parse_shard(o.shard);
  if (!o.max_memory.empty()) options.max_memory = parse_max_memory(o.max_memory);

  const std::uint64_t reps = static_cast<std::uint64_t>(plan.repetitions());
  std::cout << "sweep " << plan.name() << ": " << plan.run_count() << " runs (" << plan.configuration_count()
            << " configurations x " << reps << " repetitions)";
  if (options.shard_count > 1) {
    const std::uint64_t n = plan.run_count();
    const std::uint64_t mine =
        n > options.shard_index ? (n - options.shard_index - 1) / options.shard_count + 1 : 0;
    std::cout << ", shard " << options.shard_index << "/" << options.shard_count << ": " << mine << " runs";
  }
  std::cout << std::endl;  // before the (possibly long) run

  const RunnerReport r = run_sweep(plan, options);
  if (r.optima.needed > 0) {
    std::cout << "offline optima: " << r.optima.needed << " map and robot pairs, " << r.optima.computed
              << " computed in " << one_decimal(r.optima.seconds) << " s, " << r.optima.cached
              << " read from " << kOptimaFile << "\n";
  }
  if (!r.extended_from.empty()) {
    std::cout << "extended the results of an earlier version of the sweep file (sweep_hash "
              << r.extended_from << "): its " << r.kept << " finished runs kept, in this sweep's run order\n";
  }
  if (r.total > 0 || plan.search_units().empty()) {  // a sweep of searches alone has no runs to count
    std::cout << (r.interrupted ? "interrupted: " : "done: ") << r.ran << " ran, " << r.skipped
              << " already done, " << r.failed << " failed (end_reason error), "
              << r.total - r.ran - r.skipped << " left; " << one_decimal(r.wall_s) << " s, "
              << one_decimal(r.runs_per_s) << " runs/s on " << r.threads << " threads\n";
  }
  if (r.searches.searches > 0) {
    std::cout << "exact weight search: " << r.searches.searches
              << (r.searches.searches == 1 ? " search, " : " searches, ") << r.searches.vectors
              << " weight vectors; "
              << (r.searches.behaviours > 0 ? std::to_string(r.searches.behaviours) + " distinct behaviours; "
                                            : "")
              << (r.searches.optimal > 0 ? std::to_string(r.searches.optimal) + " optimal behaviours; " : "")
              << one_decimal(r.searches.wall_s) << " s\n";
    const auto& entries = plan.strategies();
    const bool best = std::any_of(entries.begin(), entries.end(), [](const auto& e) {
      return e.search && e.search->mode == WeightSearch::Mode::Best;
    });
    if (best && r.searches.optimal == 0 && options.shard_count <= 1) {  // a shard's files are the merge's
      std::cout
          << "note: no weight vector's runs have a value of " << plan.objective()
          << " (such as none reaching the coverage target), so no behaviour is optimal: search_best.csv "
             "is empty and searches.json's optimum is null\n";
    }
  } else if (r.searches.interrupted) {
    std::cout << "exact weight search: stopped; search_journal.jsonl keeps what it finished\n";
    for (const std::string& line : r.searches.standings) std::cout << "  " << line << "\n";
  } else if (r.searches_done_before) {
    std::cout << "exact weight search: already done (searches.json; --fresh redoes it)\n";
  } else if (!plan.search_units().empty() && options.shard_count > 1) {
    std::cout << "exact weight search: not run in a shard; run the sweep unsharded for it\n";
  }
  std::cout << "results in " << r.out_dir << "/ (runs.csv, progress.csv, manifest.json"
            << (!r.interrupted && options.shard_count == 1 ? ", summary.csv, progress_summary.csv, best.csv"
                                                           : "")
            << (r.searches.searches > 0 ? ", " + join_names(r.searches.files) : std::string())
            << (plan.competitive() ? std::string(", ") + kOptimaFile : std::string()) << ")\n";
  if (r.searches.memory_stop) {  // the machine's limit, not the user's input, stopped it
    std::cout << std::flush;
    std::cerr << "fsweep: error: " << r.searches.memory_stop->message << '\n';
    return 1;
  }
  if (r.interrupted) {
    std::cout << "rerun the same command to resume"
              << (o.sqlite ? " (results.sqlite is written once it is done)" : "") << "\n";
    return 130;
  }
  if (o.sqlite) {
    const SqliteExport e = export_sqlite(r.out_dir);
    std::cout << "wrote " << describe_export(e) << '\n';
  }
  return 0;
}

}  // namespace

Command add_run_command(CLI::App& app) {
  auto o = std::make_shared<RunCommandOptions>();
  CLI::App* sub = app.add_subcommand("run",
                                     "Run a sweep file in parallel, resumably (runs.csv, progress.csv, "
                                     "summary.csv, best.csv, manifest.json)");
  add_sweep_positionals(*sub, o->sweep_file, o->overrides);
  sub->add_option("--threads", o->threads, "Worker threads (0: all cores; at most 4 x the hardware threads)")
      ->capture_default_str();
  sub->add_flag("--fresh", o->fresh, "Delete previous outputs and start over");
  sub->add_option("--out", o->out, "Output directory (default: the sweep's output.dir or results/<name>)");
  sub->add_flag("--quiet", o->quiet, "No progress on stderr");
  sub->add_flag("--sqlite", o->sqlite,
                "Also write results.sqlite (the runs as an SQLite database, as `fsweep export-sqlite`) once "
                "the run is done");
  sub->add_option("--shard", o->shard,
                  "Run shard i of n (runs with index % n == i) into <out>/shard-i-of-n/, e.g. 0/4");
  sub->add_option(
         "--max-memory", o->max_memory,
         "Memory the exact weight searches may use, e.g. 4G, 512M, 1.5G or bytes; a search is stopped, "
         "its journal whole, at 90% of it (default: the cgroup's limit, else the machine's memory)")
      ->type_name("SIZE");
  return [o] {
    try {
      return run_command(*o);
    } catch (const IoError& e) {
      throw e.with_note(resume_note(e.os_error()));
    }
  };
}

}  // namespace fsweep::cli
