/// @file plot_command.cpp
/// `fsweep plot DIR`: the sweep's figures, drawn by tools/plot.py with Debian's python3 and
/// matplotlib (progress.png, metrics.png, and heatmap_<wi>_<wj>.png for weight searches).

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "cli/output_dir.hpp"
#include "cli/plotting.hpp"
#include "report/aggregate.hpp"

namespace fsweep::cli {
namespace {

struct PlotOptions {
  std::string dir;
  std::string out;  // empty: DIR/plots
  int top = 8;      // configurations drawn per map class, best first
};

int run_plot(const PlotOptions& o) {
  const std::string out = o.out.empty() ? o.dir + "/plots" : o.out;
  check_output_dir(out, OutputKind::Plots, "--out");  // the PNGs never go over another command's files
  for (const char* name : {"summary.csv", "progress_summary.csv", "best.csv"}) {
    if (!std::filesystem::exists(o.dir + "/" + name)) {
      std::cout << o.dir << " has no " << name << ": aggregating first\n";
      aggregate(o.dir, AggregateOptions{});
      break;
    }
  }
  return draw_plots(o.dir, out, o.top, ChildOutput::All);
}

}  // namespace

Command add_plot_command(CLI::App& app) {
  auto o = std::make_shared<PlotOptions>();
  CLI::App* sub = app.add_subcommand(
      "plot",
      "Draw a sweep's figures (progress bands, metric bars, weight heat maps) with python3-matplotlib");
  sub->add_option("DIR", o->dir, "Sweep output directory (aggregated first if summary files are missing)")
      ->required();
  sub->add_option("--out", o->out, "Directory for the PNGs (default: DIR/plots)");
  sub->add_option("--top", o->top, "Draw the best N configurations of each map class (by best.csv)")
      ->check(positive())
      ->capture_default_str();
  return [o] { return run_plot(*o); };
}

}  // namespace fsweep::cli
