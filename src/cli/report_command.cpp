/// @file report_command.cpp
/// `fsweep report DIR`: one self-contained page about a sweep's result directory, DIR/report.html
/// (report/report_page.hpp): what ran, the rankings and summaries, the figures of `fsweep plot`
/// (drawn into a temporary directory, so DIR/plots is left alone) and the trajectories of the
/// best and the worst runs, re-simulated (sweep/replay.hpp).

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "cli/plotting.hpp"
#include "core/config_error.hpp"
#include "core/files.hpp"
#include "report/html.hpp"
#include "report/report_page.hpp"
#include "sweep/replay.hpp"

namespace fsweep::cli {
namespace {

namespace fs = std::filesystem;

struct ReportOptions {
  std::string dir;
  std::string out;        // empty: DIR/report.html
  int top = 8;            // configurations per map class drawn by fsweep plot
  std::size_t rows = 30;  // rows of each table
  bool trajectories = true;
};

/// A fresh directory under the system's temp directory, removed with everything in it when the
/// value goes.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "fsweep-report-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) throw ConfigError(pattern, "cannot create a temporary directory");
    path_ = pattern;
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  TempDir(TempDir&&) = delete;
  TempDir& operator=(TempDir&&) = delete;
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  std::string path_;
};

/// The PNGs `fsweep plot` drew into `dir`: progress.png, metrics.png, then the others by name.
std::vector<PageImage> plot_images(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() == ".png") names.push_back(e.path().filename().string());
  }
  const auto order = [](const std::string& n) {
    return n == "progress.png" ? 0 : n == "metrics.png" ? 1 : 2;
  };
  std::sort(names.begin(), names.end(), [&](const std::string& a, const std::string& b) {
    return order(a) != order(b) ? order(a) < order(b) : a < b;
  });
  std::vector<PageImage> images;
  for (const auto& name : names) {
    const std::string path = (fs::path(dir) / name).string();
    auto bytes = read_file(path);
    if (!bytes) throw ConfigError(path, "cannot read the figure fsweep plot drew");
    images.push_back(plot_image(name, std::move(*bytes)));
  }
  return images;
}

/// Re-simulates the page's shown runs; a run that cannot be says why on the page.
void add_trajectories(ReportPage& page) {
  const nlohmann::json& m = page.result.manifest;
  std::optional<SweepPlan> plan;
  try {
    plan.emplace(SweepPlan::from_json(m.at("sweep"), m.value("sweep_file", std::string())));
  } catch (const ConfigError& e) {
    page.trajectories_note = std::string(
                                 "The sweep could not be rebuilt from manifest.json, so no run was "
                                 "re-simulated (is a map file not reachable from the current directory?): ") +
                             e.what();
    return;
  }
  for (const ShownRun& run : page.result.shown) {
    PageTrajectory t{run, std::nullopt, {}};
    try {
      t.replay = replay(*plan, run);
    } catch (const ConfigError& e) {
      t.error = e.what();
    }
    page.trajectories.push_back(std::move(t));
  }
}

/// The paired comparisons of the sweep's strategies when it has two or more labels: against the
/// sweep's "baseline", else its first strategy entry (paired.hpp); why not, when they fail.
void add_paired(ReportPage& page) {
  try {
    PairedTable table = paired_comparison(page.result.dir, PairedOptions{});
    std::set<std::string> labels;
    for (const PairedSide& side : table.sides) {
      if (side.source == "runs") labels.insert(side.label);
    }
    if (labels.size() < 2) return;
    const nlohmann::json& sweep = page.result.manifest["sweep"];
    page.paired_note = sweep.contains("baseline")
                           ? "the sweep's \"baseline\""
                           : "the sweep's first strategy entry; a sweep's \"baseline\" "
                             "names another, fsweep paired --baseline too";
    page.paired = std::move(table);
  } catch (const ConfigError& e) {
    page.paired_note = std::string("The strategies could not be compared: ") + e.what();
  }
}

/// Refuses an --out that is a directory, or an existing file other than a page this command
/// wrote (its generator tag, html.hpp, or the title of pages from before the tag): the page
/// never replaces another command's file.
void check_report_out(const std::string& out) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(out, ec)) {
    throw ConfigError("--out", out + " is a directory; give the page's file, e.g. " + out + "/report.html");
  }
  if (!fs::exists(out, ec)) return;
  std::ifstream in(out, std::ios::binary);
  std::string head(512, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  if (head.find(html_generator_tag(kReportGenerator)) == std::string::npos &&
      head.find("<title>fsweep report: ") == std::string::npos) {
    throw ConfigError("--out",
                      out +
                          " exists and is not a page fsweep report wrote; choose a new file or an earlier "
                          "report page");
  }
}

int run_report(const ReportOptions& o) {
  const std::string out = o.out.empty() ? o.dir + "/report.html" : o.out;
  check_report_out(out);  // before the plots are drawn
  ReportPage page;
  page.result = read_result_dir(o.dir, o.rows);
  add_paired(page);
  {
    const TempDir plots;
    if (const int code = draw_plots(o.dir, plots.path(), o.top, ChildOutput::ErrorsOnly); code != 0)
      return code;
    page.plots = plot_images(plots.path());
  }
  if (!o.trajectories) {
    page.trajectories_note = "Trajectories were left out (fsweep report --no-trajectories).";
  } else if (page.result.shown.empty()) {
    page.trajectories_note = "The directory has no runs to show.";
  } else {
    add_trajectories(page);
  }
  write_file_atomically(out, report_html(page));
  std::size_t drawn = 0;
  for (const auto& t : page.trajectories) drawn += t.replay ? 1 : 0;
  std::cout << "wrote " << out << " (" << page.plots.size() << " plots, " << drawn << " of "
            << page.trajectories.size() << " trajectories)\n";
  return 0;
}

}  // namespace

Command add_report_command(CLI::App& app) {
  auto o = std::make_shared<ReportOptions>();
  CLI::App* sub = app.add_subcommand(
      "report", "Write one self-contained HTML page about a sweep's result directory (DIR/report.html)");
  sub->add_option("DIR", o->dir,
                  "Sweep result directory (fsweep run or fsweep merge; aggregated first if needed)")
      ->required();
  sub->add_option("--out", o->out, "The page's file (default: DIR/report.html)");
  sub->add_option("--top", o->top, "Plot the best N configurations of each map class (fsweep plot --top)")
      ->check(positive())
      ->capture_default_str();
  sub->add_option(
         "--rows", o->rows,
         "Rows of each table (the ranking of each map class, best.csv, summary.csv, search_best.csv)")
      ->check(positive())
      ->capture_default_str();
  sub->add_flag("!--no-trajectories", o->trajectories,
                "Do not re-simulate the best and the worst run for their trajectory pictures");
  return [o] { return run_report(*o); };
}

}  // namespace fsweep::cli
