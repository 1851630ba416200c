/// @file aggregate_command.cpp
/// `fsweep aggregate DIR`: summary.csv, progress_summary.csv and best.csv recomputed from a
/// sweep's runs.csv and progress.csv (aggregate.hpp).

#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "core/csv_reader.hpp"
#include "report/aggregate.hpp"

namespace fsweep::cli {
namespace {

struct AggregateCommandOptions {
  std::string dir;
  std::string objective;
};

int run_aggregate(const AggregateCommandOptions& o) {
  aggregate(o.dir, AggregateOptions{o.objective});
  // Report the winner: best.csv's first row (rank, config_id, n, median, q05, q95, config).
  CsvReader best(o.dir + "/best.csv");
  std::size_t configs = 0;
  std::string winner;
  while (best.next()) {
    if (configs++ > 0) continue;
    const auto& f = best.fields();
    const std::string& median = best.header()[3];  // "<objective>.median"
    winner = "best by median " + median.substr(0, median.rfind('.')) + ": config_id " + f[1] + " (median " +
             f[3] + ", n = " + f[2] + ")";
  }
  std::cout << "wrote " << o.dir << "/summary.csv, progress_summary.csv, best.csv (" << configs
            << " configurations)\n";
  if (!winner.empty()) std::cout << winner << '\n';
  return 0;
}

}  // namespace

Command add_aggregate_command(CLI::App& app) {
  auto o = std::make_shared<AggregateCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "aggregate",
      "Recompute summary.csv, progress_summary.csv and best.csv of a sweep from runs.csv and progress.csv");
  sub->add_option("DIR", o->dir, "Sweep output directory (holding runs.csv and progress.csv)")->required();
  sub->add_option("--objective", o->objective,
                  "Ranking of best.csv: distance_to_final_coverage_m, area_per_metre, energy or "
                  "distance_to_coverage_target_m (default: the "
                  "sweep file's output.objective, else distance_to_final_coverage_m)");
  return [o] { return run_aggregate(*o); };
}

}  // namespace fsweep::cli
