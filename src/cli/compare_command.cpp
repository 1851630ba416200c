/// @file compare_command.cpp
/// `fsweep compare NEW_DIR BASELINE_DIR`: quality and speed of a sweep's outputs against a
/// baseline (compare.hpp). Prints the table, writes compare.csv and compare.html. Exit 0 no
/// regression, 1 regressions, 2 bad input.

#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "cli/output_dir.hpp"
#include "report/compare.hpp"

namespace fsweep::cli {
namespace {

struct CompareCommandOptions {
  std::string new_dir;
  std::string baseline_dir;
  std::string out;  // empty: NEW_DIR/compare
  CompareOptions compare;
};

int run_compare(const CompareCommandOptions& o) {
  const CompareReport report = compare_dirs(o.new_dir, o.baseline_dir, o.compare);
  const std::string out = o.out.empty() ? o.new_dir + "/compare" : o.out;
  create_output_dir(out, OutputKind::Compare, "--out");
  write_compare_outputs(report, out);
  std::cout << format_compare_table(report) << "wrote " << out << "/compare.csv and " << out
            << "/compare.html\n";
  return report.regressions == 0 ? 0 : 1;
}

}  // namespace

Command add_compare_command(CLI::App& app) {
  auto o = std::make_shared<CompareCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "compare",
      "Compare a sweep's outputs (and bench.json) with a baseline: exit 1 on a quality or speed regression");
  sub->add_option("NEW_DIR", o->new_dir, "Sweep output directory to check")->required();
  sub->add_option("BASELINE_DIR", o->baseline_dir, "Baseline sweep output directory (same layout)")
      ->required();
  sub->add_option("--out", o->out, "Directory for compare.csv and compare.html (default: NEW_DIR/compare)");
  sub->add_option(
         "--quality-tolerance", o->compare.quality_tolerance,
         "Relative tolerance on the q25/median/q75 of distance_m, energy, coverage of non-reproducible "
         "configurations")
      ->check(non_negative())
      ->capture_default_str();
  sub->add_option("--min-runs", o->compare.min_quantile_runs,
                  "Non-reproducible configurations with fewer runs on either side are not judged")
      ->check(positive())
      ->capture_default_str();
  sub->add_option("--significance", o->compare.significance,
                  "Quantile shifts beyond the tolerance count only when a one-sided Mann-Whitney test "
                  "over the runs gives p below this")
      ->check(CLI::Range(1e-12, 1.0))
      ->capture_default_str();
  sub->add_option("--speed-tolerance", o->compare.speed_tolerance,
                  "Slower means a time ratio above 1 + this (noise of shared machines)")
      ->check(non_negative())
      ->capture_default_str();
  sub->add_option("--min-sweep-seconds", o->compare.min_judged_sweep_wall_s,
                  "The sweep's throughput is judged only when the baseline sweep took at least this long")
      ->check(non_negative())
      ->capture_default_str();
  sub->add_flag("--strict-speed", o->compare.strict_speed,
                "Slower fails even when the machines (host, CPU) differ");
  return [o] { return run_compare(*o); };
}

}  // namespace fsweep::cli
