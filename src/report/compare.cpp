#include "report/compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>

#include "core/config_error.hpp"
#include "core/csv_format.hpp"
#include "core/csv_reader.hpp"
#include "core/statistics.hpp"
#include "planners/reproducibility.hpp"
#include "report/aggregate.hpp"
#include "report/compare_runs.hpp"
#include "report/compare_speed.hpp"
#include "report/runs_schema.hpp"

namespace fsweep {
inline namespace report {
namespace {

/// A metric compared by quantiles: name, the way it improves, the scale under which the
/// tolerance stops being relative (compare.hpp, check 2).
struct QuantileMetric {
  const char* name;
  Direction direction;
  double scale;
};
constexpr QuantileMetric kQuantileMetrics[] = {{"distance_m", Direction::Minimize, 1.0},
                                               {"energy", Direction::Minimize, 1.0},
                                               {"coverage", Direction::Maximize, 0.01}};
constexpr std::pair<const char*, double> kQuantiles[] = {{"q25", 0.25}, {"median", 0.5}, {"q75", 0.75}};

/// "+12.5%" relative to `base`, or "+0.3" when base is 0.
std::string relative_text(double delta, double base) {
  char buf[64];
  if (base != 0.0 && std::isfinite(base)) {
    std::snprintf(buf, sizeof(buf), "%+.1f%%", 100.0 * delta / std::abs(base));
  } else {
    std::snprintf(buf, sizeof(buf), "%+.4g", delta);
  }
  return buf;
}

/// Status order for a configuration: the most severe wins.
int severity(CheckStatus s) {
  switch (s) {
    case CheckStatus::Missing:
      return 6;
    case CheckStatus::Incomplete:
      return 5;
    case CheckStatus::Changed:
      return 4;
    case CheckStatus::Regressed:
      return 3;
    case CheckStatus::Improved:
      return 2;
    case CheckStatus::WithinTolerance:
      return 1;
    default:
      return 0;
  }
}

void raise(ConfigComparison& c, CheckStatus s) {
  if (severity(s) > severity(c.status)) c.status = s;
}

/// Everything the per-configuration checks need.
struct Sides {
  const RunsFile& base;
  const RunsFile& cur;
  const std::vector<std::string>& quality;  ///< quality columns both files have
  const CompareOptions& options;
  bool speed_may_fail;
};

/// Check 1: reproducible configuration, run by run.
void compare_exactly(const Sides& s, const std::vector<std::size_t>& base_rows, ConfigComparison& c,
                     std::vector<CompareCheck>& checks) {
  double worst_rel = -1.0;
  for (const std::size_t br : base_rows) {
    const auto& b = s.base.rows[br];
    const auto it = s.cur.row_of_key.find(b[s.base.run_key]);
    if (it == s.cur.row_of_key.end()) continue;
    const auto& n = s.cur.rows[it->second];
    bool changed = false;
    for (const auto& m : s.quality) {
      const std::string& bv = b[static_cast<std::size_t>(s.base.column(m))];
      const std::string& nv = n[static_cast<std::size_t>(s.cur.column(m))];
      if (cells_equal(bv, nv)) continue;
      changed = true;
      CompareCheck k;
      k.kind = "run";
      k.name = c.name + " | " + b[s.base.run_key];
      k.metric = m;
      k.baseline = bv;
      k.current = nv;
      k.status = CheckStatus::Changed;
      k.failure = true;
      const auto x = parse_number(bv);
      const auto y = parse_number(nv);
      if (x && y && std::isfinite(*x) && std::isfinite(*y)) {
        k.delta = *y - *x;
        const double rel = *x != 0.0 ? std::abs(*k.delta / *x) : std::abs(*k.delta);
        if (rel > worst_rel) {
          worst_rel = rel;
          c.worst = m + " " + relative_text(*k.delta, *x) + " (run " + b[s.base.run_key] + ")";
        }
      } else if (worst_rel < 0.0) {
        worst_rel = 0.0;
        // NOLINTNEXTLINE(performance-inefficient-string-concatenation): at most once per configuration
        c.worst = m + " '" + bv + "' -> '" + nv + "' (run " + b[s.base.run_key] + ")";
      }
      if (c.changed_runs < s.options.listed_runs_per_config) checks.push_back(k);
    }
    if (changed) ++c.changed_runs;
  }
  CompareCheck k;
  k.kind = "config";
  k.name = c.name;
  k.metric = "runs_changed";
  k.baseline = "0";
  k.current = std::to_string(c.changed_runs);
  k.status = c.changed_runs > 0 ? CheckStatus::Changed : CheckStatus::Match;
  k.failure = c.changed_runs > 0;
  checks.push_back(k);
  raise(c, k.status);
}

/// Check 2: other configurations, by quantiles and share of successful runs.
void compare_quantiles(const Sides& s, const std::vector<std::size_t>& base_rows,
                       const std::vector<std::size_t>& cur_rows, ConfigComparison& c,
                       std::vector<CompareCheck>& checks) {
  if (base_rows.size() < s.options.min_quantile_runs || cur_rows.size() < s.options.min_quantile_runs) {
    // Quantiles of a handful of runs of a planner that varies from run to run are noise
    // (the nightly suite's PRM* configurations of 2 runs moved by tens of percent).
    CompareCheck k;
    k.kind = "config";
    k.name = c.name;
    k.metric = "runs";
    k.baseline = std::to_string(base_rows.size());
    k.current = std::to_string(cur_rows.size());
    k.status = CheckStatus::NotJudged;
    checks.push_back(k);
    c.worst = "fewer than " + std::to_string(s.options.min_quantile_runs) + " runs: not judged";
    if (c.status == CheckStatus::Match) c.status = CheckStatus::NotJudged;
    return;
  }
  const double tol = s.options.quality_tolerance;
  double worst_badness = -std::numeric_limits<double>::infinity();
  double best_badness = std::numeric_limits<double>::infinity();
  std::string worst_text, best_text;
  for (const QuantileMetric& m : kQuantileMetrics) {
    if (std::find(s.quality.begin(), s.quality.end(), m.name) == s.quality.end()) continue;
    const auto bv = sorted_values(s.base, base_rows, m.name);
    const auto nv = sorted_values(s.cur, cur_rows, m.name);
    if (bv.empty() || nv.empty()) continue;
    // One-sided tests: is NEW worse (larger for lower-is-better metrics), is it better?
    const bool lower_is_better = m.direction == Direction::Minimize;
    const double p_worse = lower_is_better ? mann_whitney_greater_p(bv, nv) : mann_whitney_greater_p(nv, bv);
    const double p_better = lower_is_better ? mann_whitney_greater_p(nv, bv) : mann_whitney_greater_p(bv, nv);
    for (const auto& [qname, q] : kQuantiles) {
      CompareCheck k;
      k.kind = "config";
      k.name = c.name;
      k.metric = std::string(m.name) + "." + qname;
      const double b = quantile_sorted(bv, q);
      const double n = quantile_sorted(nv, q);
      k.baseline = format_number(b);
      k.current = format_number(n);
      k.delta = n - b;
      const double band = tol * std::max(std::abs(b), m.scale);
      k.tolerance = band;
      k.p_value = p_worse;
      const double worse = lower_is_better ? n - b : b - n;  // > 0: worse
      if (worse > band && p_worse < s.options.significance) {
        k.status = CheckStatus::Regressed;
        k.failure = true;
      } else if (-worse > band && p_better < s.options.significance) {
        k.status = CheckStatus::Improved;
      } else {
        k.status = CheckStatus::WithinTolerance;
      }
      const double badness = band > 0.0 ? worse / band : worse;
      const std::string text = k.metric + " " + relative_text(n - b, b);
      if (badness > worst_badness) {
        worst_badness = badness;
        worst_text = text;
      }
      if (badness < best_badness) {
        best_badness = badness;
        best_text = text;
      }
      raise(c, k.status);
      checks.push_back(k);
    }
  }
  CompareCheck k;
  k.kind = "config";
  k.name = c.name;
  k.metric = "success_share";
  const double b = success_share(s.base, base_rows);
  const double n = success_share(s.cur, cur_rows);
  k.baseline = format_number(b);
  k.current = format_number(n);
  k.delta = n - b;
  k.tolerance = 0.0;
  // The same test on the outcomes: 1 for a successful run, 0 otherwise (NEW worse = smaller).
  const auto outcomes = [&](const RunsFile& t, const std::vector<std::size_t>& rows) {
    std::vector<double> v;
    v.reserve(rows.size());
    const auto col = static_cast<std::size_t>(t.column(kEndReasonColumn));
    for (const std::size_t r : rows) v.push_back(successful_end(t.rows[r][col]) ? 1.0 : 0.0);
    return v;
  };
  k.p_value = mann_whitney_greater_p(outcomes(s.cur, cur_rows), outcomes(s.base, base_rows));
  k.status = n < b - 1e-12 && *k.p_value < s.options.significance ? CheckStatus::Regressed
                                                                  : CheckStatus::WithinTolerance;
  k.failure = k.status == CheckStatus::Regressed;
  if (k.failure) worst_text = "success_share " + format_number(b) + " -> " + format_number(n);
  raise(c, k.status);
  checks.push_back(k);
  c.worst = c.status == CheckStatus::Improved ? best_text : worst_text;
}

/// Median wall_time_s ratio (compare.hpp, check 4).
CompareCheck wall_time_check(const Sides& s, const std::vector<std::size_t>& base_rows,
                             const std::vector<std::size_t>& cur_rows, const std::string& name) {
  const auto bv = sorted_values(s.base, base_rows, "wall_time_s");
  const auto nv = sorted_values(s.cur, cur_rows, "wall_time_s");
  const std::optional<double> b = bv.empty() ? std::nullopt : std::optional<double>(quantile_sorted(bv, 0.5));
  const std::optional<double> n = nv.empty() ? std::nullopt : std::optional<double>(quantile_sorted(nv, 0.5));
  // Informational only: a run's wall time depends on what runs beside it (other threads, and
  // OMPL planners wait for a process-wide lock), so the same configuration measured 1x-3x apart
  // between two runs of the nightly suite on one machine.
  CompareCheck k = time_ratio_check("speed", name, "wall_time_s.median", b, n, s.options.speed_tolerance,
                                    /*may_fail=*/false);
  if (b && *b < s.options.min_judged_wall_time_s) {
    k.status = CheckStatus::NotJudged;
    k.failure = false;
  }
  return k;
}

/// `planner.<param>` values of a configuration's first row.
bool reproducible_config(const RunsFile& t, const std::vector<std::size_t>& rows) {
  const auto& f = t.rows[rows.front()];
  const int planner = t.column(kPlannerColumn);
  const std::string prefix = std::string(kPlannerColumn) + ".";
  std::map<std::string, std::string> params;
  for (std::size_t i = 0; i < t.header.size(); ++i) {
    if (t.header[i].starts_with(prefix)) params[t.header[i].substr(prefix.size())] = f[i];
  }
  return planner >= 0 && planner_reproducible(f[static_cast<std::size_t>(planner)], params);
}

void warn_one_sided(CompareReport& r, const std::vector<std::string>& a, const std::vector<std::string>& b,
                    const std::string& what) {
  for (const auto& n : a) {
    if (std::find(b.begin(), b.end(), n) == b.end())
      r.warnings.push_back(std::string(what).append(" '").append(n) + "'");
  }
}

/// The names of `base` that `cur` also has, in base's order; each name of one side only is a
/// warning ("<what> only in the baseline<not_compared>:" / "... only in NEW...").
std::vector<std::string> shared_names(CompareReport& r, const std::vector<std::string>& base,
                                      const std::vector<std::string>& cur, const std::string& what,
                                      const std::string& not_compared) {
  std::vector<std::string> shared;
  for (const auto& n : base) {
    if (std::find(cur.begin(), cur.end(), n) != cur.end()) shared.push_back(n);
  }
  warn_one_sided(r, base, cur, what + " only in the baseline" + not_compared + ":");
  warn_one_sided(r, cur, base, what + " only in NEW" + not_compared + ":");
  return shared;
}

void check_options(const std::string& new_dir, const std::string& baseline_dir,
                   const CompareOptions& options) {
  if (!(options.quality_tolerance >= 0.0)) throw ConfigError("--quality-tolerance", "must be >= 0");
  if (!(options.speed_tolerance >= 0.0)) throw ConfigError("--speed-tolerance", "must be >= 0");
  if (!(options.significance > 0.0 && options.significance < 1.0)) {
    throw ConfigError("--significance", "must be in (0, 1)");
  }
  if (options.min_quantile_runs < 1) throw ConfigError("--min-runs", "must be >= 1");
  for (const std::string& d : {new_dir, baseline_dir}) {
    if (!std::filesystem::is_directory(d)) throw ConfigError(d, "not a directory");
  }
}

/// Aggregates a side whose summary.csv is missing or older than its runs.csv (its box plots),
/// saying so; warns when it cannot (no progress.csv).
void refresh_summaries(CompareReport& r) {
  for (const std::string& d : {r.new_dir, r.baseline_dir}) {
    const std::string summary = d + "/summary.csv";
    const bool missing = !std::filesystem::exists(summary);
    if (!missing &&
        std::filesystem::last_write_time(summary) >= std::filesystem::last_write_time(d + "/runs.csv")) {
      continue;
    }
    const std::string why = missing ? " has no summary.csv" : ": summary.csv is older than runs.csv";
    if (!std::filesystem::exists(d + "/progress.csv")) {
      r.warnings.push_back(d + why + " and no progress.csv to aggregate: its box plots " +
                           (missing ? "are left out" : "may be stale"));
      continue;
    }
    aggregate(d, AggregateOptions{});
    r.notes.push_back(d + why + ": aggregated it first");
  }
}

/// Warnings about the two sides as wholes: different sweeps, a new side that did not complete,
/// different machines (whose speed flags are then informational).
void warn_about_sides(CompareReport& r, const ManifestFacts& base, const ManifestFacts& cur,
                      const BenchFile* base_bench, const BenchFile* cur_bench,
                      const CompareOptions& options) {
  if (base.sweep_hash && cur.sweep_hash && *base.sweep_hash != *cur.sweep_hash) {
    r.sweep_hash_differs = true;
    r.warnings.push_back(
        "the sweeps differ (sweep_hash " + *base.sweep_hash + " (baseline) vs " + *cur.sweep_hash +
        " (new)): only the configurations and runs both have are compared (compare checks a "
        "sweep against an earlier run of itself; to compare strategies within one sweep, use "
        "fsweep paired)");
  }
  if (cur.status && *cur.status != "complete") {
    r.warnings.push_back(cur.path + ": status '" + *cur.status + "', not 'complete'");
  }
  const auto differences = machine_differences(base, cur, base_bench, cur_bench);
  r.same_machine = differences.empty();
  for (const auto& d : differences) {
    r.warnings.push_back("different machine: " + d + "; speed flags are informational" +
                         (options.strict_speed ? " (but --strict-speed is set)" : " unless --strict-speed"));
  }
}

/// The configuration `c` one side lacks: a check of kind "config" (missing from NEW fails).
void compare_one_sided(ConfigComparison& c, bool in_baseline, CompareReport& r) {
  c.status = in_baseline ? CheckStatus::Missing : CheckStatus::New;
  c.failure = in_baseline;
  CompareCheck k;
  k.kind = "config";
  k.name = c.name;
  k.metric = "runs";
  k.baseline = std::to_string(c.baseline_runs);
  k.current = std::to_string(c.new_runs);
  k.status = c.status;
  k.failure = c.failure;
  r.checks.push_back(k);
}

/// A configuration both sides have (its rows `b_rows`, `n_rows`): baseline runs NEW lacks
/// (listed up to options.listed_runs_per_config), then its quality exactly or by quantiles.
void compare_both_sided(const Sides& s, const std::vector<std::size_t>& b_rows,
                        const std::vector<std::size_t>& n_rows, ConfigComparison& c, CompareReport& r) {
  std::size_t missing_runs = 0;
  for (const std::size_t br : b_rows) {
    const std::string& key = s.base.rows[br][s.base.run_key];
    if (s.cur.row_of_key.count(key) != 0) continue;
    if (missing_runs++ < s.options.listed_runs_per_config) {
      CompareCheck k;
      k.kind = "run";
      k.name = c.name + " | " + key;
      k.metric = "run_key";
      k.baseline = key;
      k.status = CheckStatus::Missing;
      k.failure = true;
      r.checks.push_back(k);
    }
  }
  if (c.reproducible) {
    compare_exactly(s, b_rows, c, r.checks);
  } else {
    compare_quantiles(s, b_rows, n_rows, c, r.checks);
  }
  if (missing_runs > 0) {
    raise(c, CheckStatus::Incomplete);
    c.worst = std::to_string(missing_runs) + " of " + std::to_string(b_rows.size()) + " runs missing" +
              (c.worst.empty() ? "" : "; " + c.worst);
  }
  c.failure = severity(c.status) >= severity(CheckStatus::Regressed);
}

}  // namespace

std::string to_string(CheckStatus status) {
  switch (status) {
    case CheckStatus::Match:
      return "match";
    case CheckStatus::Changed:
      return "changed";
    case CheckStatus::WithinTolerance:
      return "within tolerance";
    case CheckStatus::Regressed:
      return "regressed";
    case CheckStatus::Improved:
      return "improved";
    case CheckStatus::Missing:
      return "missing";
    case CheckStatus::Incomplete:
      return "incomplete";
    case CheckStatus::New:
      return "new";
    case CheckStatus::Slower:
      return "slower";
    case CheckStatus::Faster:
      return "faster";
    case CheckStatus::NotJudged:
      return "not judged";
  }
  return "unknown";
}

CompareReport compare_dirs(const std::string& new_dir, const std::string& baseline_dir,
                           const CompareOptions& options) {
  check_options(new_dir, baseline_dir, options);
  CompareReport r;
  r.new_dir = new_dir;
  r.baseline_dir = baseline_dir;
  r.speed_tolerance = options.speed_tolerance;
  for (const auto& m : kQuantileMetrics) r.box_metrics.emplace_back(m.name);

  // 1. Inputs: runs, manifests, benchmarks; summaries (aggregated when missing).
  const RunsFile base = read_runs_file(baseline_dir + "/runs.csv");
  const RunsFile cur = read_runs_file(new_dir + "/runs.csv");
  const ManifestFacts base_manifest = read_manifest_facts(baseline_dir + "/manifest.json");
  const ManifestFacts cur_manifest = read_manifest_facts(new_dir + "/manifest.json");
  const auto base_bench = read_bench_file(baseline_dir + "/bench.json");
  const auto cur_bench = read_bench_file(new_dir + "/bench.json");
  const BenchFile* base_bench_ptr = base_bench ? &*base_bench : nullptr;
  const BenchFile* cur_bench_ptr = cur_bench ? &*cur_bench : nullptr;
  refresh_summaries(r);
  warn_about_sides(r, base_manifest, cur_manifest, base_bench_ptr, cur_bench_ptr, options);

  // 2. Shared columns.
  const std::vector<std::string> key_names =
      shared_names(r, base.config_names, cur.config_names, "config column", "");
  const std::vector<std::string> quality =
      shared_names(r, base.quality_names, cur.quality_names, "metric column", " (not compared)");

  // 3. Configurations of both sides and their labels.
  const Grouping bg = group(base, columns_of(base, key_names));
  const Grouping ng = group(cur, columns_of(cur, key_names));
  std::vector<std::string> keys = bg.keys;
  for (const auto& k : ng.keys) {
    if (bg.rows.count(k) == 0) keys.push_back(k);
  }
  std::vector<std::vector<std::string>> values;
  values.reserve(keys.size());
  for (const auto& k : keys) values.push_back(split_config_key(k));
  const auto positions = label_positions(key_names, values);
  for (const std::size_t p : positions) r.label_columns.push_back(key_names[p]);
  const auto base_boxes = read_boxes(baseline_dir + "/summary.csv", key_names, r.box_metrics);
  const auto cur_boxes = read_boxes(new_dir + "/summary.csv", key_names, r.box_metrics);
  const auto box_of = [&](const auto& boxes, const std::string& key) {
    const auto it = boxes.find(key);
    return it == boxes.end() ? std::vector<std::optional<BoxStats>>(r.box_metrics.size()) : it->second;
  };

  // 4. Per configuration: quality, then median wall time.
  const Sides sides{base, cur, quality, options, r.same_machine || options.strict_speed};
  std::vector<CompareCheck> speed_checks;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    ConfigComparison c;
    for (const std::size_t p : positions) c.label.push_back(values[i][p]);
    for (std::size_t j = 0; j < c.label.size(); ++j) {
      const std::string& column = r.label_columns[j];
      const bool plain =
          column == kMapClassColumn || column == kStrategyLabelColumn || column == kPlannerColumn;
      c.name += (j ? " | " : "") + (plain ? c.label[j] : column + "=" + c.label[j]);
    }
    const auto b_it = bg.rows.find(keys[i]);
    const auto n_it = ng.rows.find(keys[i]);
    const auto* b_rows = b_it == bg.rows.end() ? nullptr : &b_it->second;
    const auto* n_rows = n_it == ng.rows.end() ? nullptr : &n_it->second;
    c.baseline_runs = b_rows ? b_rows->size() : 0;
    c.new_runs = n_rows ? n_rows->size() : 0;
    c.reproducible = b_rows ? reproducible_config(base, *b_rows) : reproducible_config(cur, *n_rows);
    c.baseline_box = box_of(base_boxes, keys[i]);
    c.new_box = box_of(cur_boxes, keys[i]);
    if (!b_rows || !n_rows) {
      compare_one_sided(c, b_rows != nullptr, r);
    } else {
      compare_both_sided(sides, *b_rows, *n_rows, c, r);
      speed_checks.push_back(wall_time_check(sides, *b_rows, *n_rows, c.name));
    }
    r.configs.push_back(c);
  }
  r.checks.insert(r.checks.end(), speed_checks.begin(), speed_checks.end());

  // 5. Sweep throughput and micro-benchmarks; the verdict.
  add_sweep_speed_checks(r, base_manifest, cur_manifest, base_bench_ptr, cur_bench_ptr, options);
  for (const auto& c : r.configs) r.regressions += c.failure;
  for (const auto& k : r.checks) r.regressions += (k.kind == "speed" || k.kind == "bench") && k.failure;
  return r;
}

}  // namespace report
}  // namespace fsweep
