/// @file merge_command.cpp
/// `fsweep merge DIR`: joins the shards DIR/shard-i-of-n/ of a sweep and aggregates them
/// (merge.hpp). Exit 0 merged, 1 incomplete or duplicate runs or the memory guard (nothing
/// written), 2 bad input.

#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "cli/output_dir.hpp"
#include "cli/problem_list.hpp"
#include "core/memory_limit.hpp"
#include "sweep/merge.hpp"

namespace fsweep::cli {
namespace {

struct MergeCommandOptions {
  std::string dir;
  std::string objective;
  std::string max_memory;
};

int run_merge(const MergeCommandOptions& o) {
  SearchMemoryGuard memory;
  memory.limit = o.max_memory.empty() ? default_memory_limit() : parse_max_memory(o.max_memory);
  check_output_dir(o.dir, OutputKind::Sweep, "DIR (and --out of the sharded runs)");
  const MergeReport r = merge_shards(o.dir, o.objective, memory);
  if (!r.memory_stop.empty()) {
    std::cerr << "fsweep merge: " << o.dir << ": " << r.memory_stop << "\n";
    return 1;
  }
  if (!r.written) {
    std::cerr << "fsweep merge: " << o.dir << ": " << r.problems.size() << " problem(s), nothing "
              << (r.search_status.empty() ? "written" : "merged") << " (" << r.rows
              << " runs.csv rows in the shards of a " << r.shard_count << "-way split, sweep of " << r.total
              << " runs):\n";
    print_problems(std::cerr, r.problems);
    if (!r.search_status.empty())
      std::cerr << "(only the searches' joint status was written" << r.search_status << ")\n";
    std::cerr
        << "rerun the failed or missing shards (fsweep run SWEEP --shard i/N resumes a partial shard)\n";
    return 1;
  }
  std::cout << "merged " << r.shard_count << " shards (" << r.total << " runs) into " << o.dir
            << "/runs.csv, progress.csv, manifest.json; wrote summary.csv, progress_summary.csv, best.csv\n";
  if (r.searches > 0) {
    std::cout << "merged " << r.searches << " exact weight search" << (r.searches == 1 ? "" : "es")
              << " into behaviours.csv, search_best.csv, ..., searches.json\n";
  }
  return 0;
}

}  // namespace

Command add_merge_command(CLI::App& app) {
  auto o = std::make_shared<MergeCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "merge",
      "Join the shards (DIR/shard-i-of-N/) of a sweep into DIR/runs.csv and progress.csv and aggregate them");
  sub->add_option("DIR", o->dir, "Sweep output directory holding the shard-i-of-N directories")->required();
  sub->add_option("--objective", o->objective,
                  "Ranking of best.csv: distance_to_final_coverage_m, area_per_metre, energy or "
                  "distance_to_coverage_target_m (default: the "
                  "sweep file's output.objective, else distance_to_final_coverage_m)");
  sub->add_option("--max-memory", o->max_memory,
                  "Memory the merge of exact weight searches may use, e.g. 4G, 512M, 1.5G or bytes; reading "
                  "the shards' journals back past 90% of it stops the merge, nothing written (default: the "
                  "cgroup's limit, else the machine's memory)")
      ->type_name("SIZE");
  return [o] { return run_merge(*o); };
}

}  // namespace fsweep::cli
