// The text table and compare.csv of `fsweep compare` (compare.hpp), and writing the outputs.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <system_error>

#include "core/config_error.hpp"
#include "core/csv_format.hpp"
#include "core/files.hpp"
#include "report/compare.hpp"

namespace fsweep {
inline namespace report {
namespace {

std::string padded(const std::string& s, std::size_t width) {
  return s.size() >= width ? s : s + std::string(width - s.size(), ' ');
}

std::string ratio_text(const std::optional<double>& ratio) {
  if (!ratio) return "";
  char buf[32];
  std::snprintf(buf, sizeof(buf), "x%.2f", *ratio);
  return buf;
}

/// A value of a speed line: 4 significant digits when it is a number.
std::string short_value(const std::string& text) {
  if (text.empty()) return "-";
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0') return text;
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.4g", v);
  return buf;
}

std::string optional_number(const std::optional<double>& v) { return v ? format_number(*v) : std::string(); }

/// One speed line: kind, name, metric, baseline -> new, ratio, status.
void speed_line(std::ostringstream& out, const CompareCheck& k) {
  out << "  " << padded(k.kind, 6) << ' ' << padded(k.name + " " + k.metric, 48) << ' '
      << padded(short_value(k.baseline) + " -> " + short_value(k.current), 24) << ' '
      << padded(ratio_text(k.ratio), 7) << ' ' << to_string(k.status)
      << (k.status == CheckStatus::Slower && !k.failure ? " (informational)" : "")
      << (k.failure ? "  FAIL" : "") << '\n';
}

}  // namespace

std::string format_compare_table(const CompareReport& r) {
  std::ostringstream out;
  out << "fsweep compare: new " << r.new_dir << " vs baseline " << r.baseline_dir << '\n';
  for (const auto& w : r.warnings) out << "WARNING: " << w << '\n';
  for (const auto& n : r.notes) out << "note: " << n << '\n';

  // 1. Quality, one line per configuration.
  std::vector<std::string> head = r.label_columns;
  head.insert(head.end(), {"kind", "runs b/n", "status", "worst difference"});
  std::vector<std::vector<std::string>> rows;
  for (const auto& c : r.configs) {
    std::vector<std::string> row = c.label;
    row.push_back(c.reproducible ? "exact" : "quantiles");
    row.push_back(std::to_string(c.baseline_runs) + "/" + std::to_string(c.new_runs));
    row.push_back(to_string(c.status) + (c.failure ? " FAIL" : ""));
    row.push_back(c.worst);
    rows.push_back(std::move(row));
  }
  std::vector<std::size_t> width(head.size());
  for (std::size_t i = 0; i < head.size(); ++i) {
    width[i] = head[i].size();
    for (const auto& row : rows) width[i] = std::max(width[i], row[i].size());
  }
  out << "\nquality per configuration (exact: reproducible planner, every run must match; quantiles: q25, "
         "median, q75 of distance_m, energy, coverage; regressed when worse beyond the tolerance and "
         "significant by a one-sided Mann-Whitney test)\n";
  auto print_row = [&](const std::vector<std::string>& row) {
    std::string line;
    for (std::size_t i = 0; i < row.size(); ++i)
      line += (i ? "  " : "") + (i + 1 < row.size() ? padded(row[i], width[i]) : row[i]);
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out << line << '\n';
  };
  print_row(head);
  for (const auto& row : rows) print_row(row);

  // 2. Differing and missing runs (those listed in the checks).
  bool any_run = false;
  for (const auto& k : r.checks) {
    if (k.kind != "run") continue;
    if (!any_run) out << "\nruns that differ or are missing (first few per configuration):\n";
    any_run = true;
    if (k.status == CheckStatus::Missing) {
      out << "  " << k.name << ": missing in new\n";
    } else {
      out << "  " << k.name << ": " << k.metric << " " << k.baseline << " -> " << k.current << '\n';
    }
  }

  // 3. Speed: the sweep, the benchmarks, and the configurations outside the tolerance.
  char tol[96];
  std::snprintf(tol, sizeof(tol), "slower above x%.2f, faster below x%.2f", 1.0 + r.speed_tolerance,
                1.0 / (1.0 + r.speed_tolerance));
  out << "\nspeed (time ratios new / baseline; " << tol << (r.same_machine ? "" : "; different machine")
      << ")\n";
  std::size_t within = 0, not_judged = 0;
  for (const auto& k : r.checks) {
    if (k.kind == "speed" && k.name != "sweep") {
      if (k.status == CheckStatus::WithinTolerance) {
        ++within;
        continue;
      }
      if (k.status == CheckStatus::NotJudged) {
        ++not_judged;
        continue;
      }
    }
    if (k.kind == "speed" || k.kind == "bench") speed_line(out, k);
  }
  out << "  configurations' median wall_time_s: " << within << " within tolerance, " << not_judged
      << " not judged (baseline median below the minimum)\n";

  out << "\ncompare: ";
  if (r.regressions == 0) {
    out << "no regressions\n";
  } else {
    out << r.regressions << (r.regressions == 1 ? " regression\n" : " regressions\n");
  }
  return out.str();
}

std::string compare_csv(const CompareReport& r) {
  std::string out = "kind,name,metric,baseline,new,delta,ratio,tolerance,p_value,status,failure\n";
  for (const auto& k : r.checks) {
    const std::vector<std::string> f{k.kind,
                                     k.name,
                                     k.metric,
                                     k.baseline,
                                     k.current,
                                     optional_number(k.delta),
                                     optional_number(k.ratio),
                                     optional_number(k.tolerance),
                                     optional_number(k.p_value),
                                     to_string(k.status),
                                     k.failure ? "yes" : "no"};
    (out += csv_record(f)) += '\n';
  }
  return out;
}

void write_compare_outputs(const CompareReport& report, const std::string& out_dir) {
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) throw ConfigError(out_dir, "cannot create the output directory: " + ec.message());
  write_file_atomically(out_dir + "/compare.csv", compare_csv(report));
  write_file_atomically(out_dir + "/compare.html", compare_html(report));
}

}  // namespace report
}  // namespace fsweep
