/// @file paired_command.cpp
/// `fsweep paired DIR`: every strategy of a sweep against a baseline, pair by pair
/// (report/paired.hpp): paired.csv and paired.json, and a table on the terminal.

#include <cctype>
#include <filesystem>
#include <iostream>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "cli/output_dir.hpp"
#include "cli/plotting.hpp"
#include "core/config_error.hpp"
#include "core/readable_number.hpp"
#include "report/config_names.hpp"
#include "report/paired.hpp"
#include "report/runs_schema.hpp"

namespace fsweep::cli {
namespace {

/// At most this many bootstrap resamples per row.
constexpr std::uint64_t kMaxResamples = 10'000'000;

struct PairedCommandOptions {
  std::string dir;
  std::string out;  // empty: DIR
  PairedOptions paired;
  bool curves = false;
};

/// "m" -> " m", "" -> "".
std::string with_space(std::string_view unit) {
  return unit.empty() ? std::string() : " " + std::string(unit);
}

/// A p-value for reading: 2 significant digits, "<0.0001" below.
std::string p_text(const std::optional<double>& p) {
  if (!p) return "-";
  if (*p < 1e-4) return "<0.0001";
  return readable_number(*p, 2);
}

/// One line of a row: the side, its pairs, the differences with the interval, W/T/L and p.
void print_row(const PairedRow& r, std::string_view unit, std::size_t width) {
  const auto diff = [&](double v) { return readable_number(v, 4, Sign::Always); };
  std::string ci =
      r.ci ? "[" + diff(r.ci->lo) + ", " + diff(r.ci->hi) + "]" : "[no interval: 1 map instance]";
  if (r.n_pairs == 0) ci = "";
  std::string line = "    " + r.side + std::string(width - r.side.size() + 2, ' ');
  line += std::to_string(r.n_pairs) + " pairs";
  if (r.n_pairs == 0) {
    std::cout << line << " (unpaired " << r.unpaired << ", mixed ends " << r.mixed_end << ", no value "
              << r.no_value << ")\n";
    return;
  }
  line += ", mean " + diff(r.mean_diff) + with_space(unit) + " " + ci + ", median " + diff(r.median_diff) +
          with_space(unit) + ", " + readable_number(r.rel_diff_pct, 2, Sign::Always) + "%";
  line += ", W/T/L " + std::to_string(r.wins) + "/" + std::to_string(r.ties) + "/" + std::to_string(r.losses);
  line += ", p " + p_text(r.wilcoxon ? std::optional<double>(r.wilcoxon->p_value) : std::nullopt) + " (" +
          std::string(to_string(r.wilcoxon->method)) + "; Holm " + p_text(r.p_holm) + ")";
  if (r.mixed_end > 0 || r.unpaired > 0)
    line += "; left out: " + std::to_string(r.mixed_end) + " mixed ends, " + std::to_string(r.unpaired) +
            " unpaired";
  std::cout << line << '\n';
}

void print_table(const PairedTable& t) {
  std::size_t width = 0;
  for (const auto& r : t.rows) width = std::max(width, r.side.size());
  std::string block, metric;
  for (const PairedRow& r : t.rows) {
    std::string b = (r.source == "runs" ? "" : r.source + ", ") + "map class " + r.map_class;
    for (std::size_t v = 0; v < r.variant.size(); ++v)
      b += ", " + column_title(t.variant_columns[v]) + "=" + r.variant[v];
    if (b != block) {
      std::cout << b << ":\n";
      block = b;
      metric.clear();
    }
    if (r.metric != metric) {
      metric = r.metric;
      const bool lower = metric_direction(metric) == Direction::Minimize;
      std::cout << "  " << metric << " minus " << r.baseline << "'s (" << (lower ? "lower" : "higher")
                << " is better; W/T/L: wins, ties, losses):\n";
    }
    print_row(r, r.unit, width);
  }
}

int run_paired(const PairedCommandOptions& o) {
  const std::string out = o.out.empty() ? o.dir : o.out;
  if (!o.out.empty()) create_output_dir(out, OutputKind::Paired, "--out");
  const PairedTable table = paired_comparison(o.dir, o.paired);
  print_table(table);
  for (const auto& note : table.notes) std::cout << "note: " << note << '\n';
  write_paired(out, table, o.paired);
  std::cout << "wrote " << out << "/paired.csv and paired.json (bootstrap: " << o.paired.resamples
            << " resamples of the map instances, seed " << o.paired.seed << ")\n";
  if (!o.curves) return 0;
  // The coverage curves (tools/paired_compare.py, Mei 2006 section V-C) of each label side.
  std::set<std::string> done;
  for (const PairedSide& side : table.sides) {
    if (side.source != "runs" || side.name != side.label || side.name == table.baseline) continue;
    if (!done.insert(side.name).second) continue;
    std::string prefix = out;
    prefix += "/paired_curves_";
    for (const char c : side.name) prefix += std::isalnum(static_cast<unsigned char>(c)) != 0 ? c : '_';
    if (const int code = run_tool_script(
            "paired_compare.py",
            {o.dir, "--a", side.name, "--b", table.baseline, "--out", prefix, "--plot", prefix + "_"},
            ChildOutput::All);
        code != 0)
      return code;
  }
  return 0;
}

}  // namespace

Command add_paired_command(CLI::App& app) {
  auto o = std::make_shared<PairedCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "paired",
      "Compare every strategy of a sweep with a baseline, pair by pair on the same map instance, robot, "
      "planner "
      "and seed: differences, bootstrap intervals, signed-rank tests, wins/ties/losses (paired.csv)");
  sub->add_option("DIR", o->dir, "Sweep output directory (holding runs.csv and manifest.json)")->required();
  sub->add_option("--baseline", o->paired.baseline,
                  "The side the others are compared with: a strategy label, or the name paired.csv gives a "
                  "configuration (default: the sweep's \"baseline\", else its first strategy entry)");
  sub->add_option(
      "--metric", o->paired.metrics,
      "A metric column to compare (repeat for several; default: distance_to_final_coverage_m, energy, "
      "area_per_metre)");
  sub->add_option("--resamples", o->paired.resamples, "Bootstrap resamples per row")
      ->check(CLI::Range(std::uint64_t{1}, kMaxResamples))
      ->capture_default_str();
  sub->add_option("--seed", o->paired.seed, "Seed of the bootstrap")->capture_default_str();
  sub->add_option("--out", o->out, "Directory for paired.csv and paired.json (default: DIR)");
  sub->add_flag("--curves", o->curves,
                "Also the coverage-curve analysis of tools/paired_compare.py (Mei 2006 section V-C) for each "
                "strategy label against the baseline, with its plots, into the output directory");
  return [o] { return run_paired(*o); };
}

}  // namespace fsweep::cli
