#include "report/aggregate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "core/config_error.hpp"
#include "core/csv_format.hpp"
#include "core/csv_reader.hpp"
#include "core/files.hpp"
#include "core/json_text.hpp"
#include "core/random.hpp"
#include "core/replacing_file.hpp"
#include "core/statistics.hpp"
#include "report/runs_schema.hpp"
#include "sim/run_result.hpp"

namespace fsweep {
inline namespace report {
namespace {

/// Distances closer than this are the same (the simulator's progress-grid tolerance).
constexpr double kSameDistanceM = 1e-9;

/// One configuration of runs.csv: its config values, run count, end reasons and metric values.
struct Configuration {
  std::vector<std::string> values;
  std::uint64_t n = 0;
  /// Hashes of the runs' map instance and outcome (n_distinct: the number of distinct ones).
  std::unordered_set<std::uint64_t> distinct;
  std::vector<std::uint64_t> end_counts;     // parallel to RunsTable::end_reasons
  std::vector<std::vector<double>> metrics;  // parallel to RunsTable::metric_names
};

/// runs.csv grouped by configuration.
struct RunsTable {
  std::string path;
  std::vector<std::string> config_names;
  std::vector<std::string> metric_names;
  std::vector<std::string> end_reasons;  // every EndReason, then unknown ones by first appearance
  std::vector<Configuration> configs;    // by first appearance = config_id
  std::unordered_map<std::string, std::size_t> config_of_run;  // run_key -> config_id
};

/// Progress samples of one configuration (see progress_summary.csv in aggregate.hpp).
struct ProgressBands {
  /// Grid distance -> explored area of every run sampled there (all samples but each run's last).
  std::map<double, std::vector<double>> grid;
  /// Per run: its last grid sample's distance (-inf if none) and its final explored area.
  std::vector<std::pair<double, double>> finals;
  double max_final_m = -std::numeric_limits<double>::infinity();
};

/// A CSV file written to a temp file and renamed into place by close() (core/replacing_file.hpp:
/// a failed write throws IoError and leaves the old file).
class CsvOut {
 public:
  explicit CsvOut(std::string path) : file_(std::move(path)) {}
  void row(const std::vector<std::string>& fields) { file_.write(csv_record(fields) + '\n'); }
  void close() { file_.commit(); }

 private:
  ReplacingFile file_;
};

RunsTable read_runs(const std::string& path) {
  RunsTable t;
  t.path = path;
  CsvReader in(path);
  const RunsHeader header(in.header(), path);
  const std::size_t run_key = header.run_key();
  const std::size_t end_reason = header.end_reason();
  const std::vector<std::size_t>& config_cols = header.config();
  const std::vector<std::size_t>& metric_cols = header.metrics();
  t.config_names = header.names_of(config_cols);
  t.metric_names = header.names_of(metric_cols);
  for (int r = static_cast<int>(EndReason::Complete); r <= static_cast<int>(EndReason::Error); ++r) {
    t.end_reasons.emplace_back(to_string(static_cast<EndReason>(r)));
  }

  // A run's identity for n_distinct: its map instance (the instance columns but the seed) and its
  // outcome (end reason and every metric but the effort columns).
  std::vector<std::size_t> identity_cols;
  for (std::size_t c = 0; c < header.names().size(); ++c) {
    if (header.role(c) == ColumnRole::Instance && header.names()[c] != kSeedColumn)
      identity_cols.push_back(c);
  }
  identity_cols.insert(identity_cols.end(), header.quality().begin(), header.quality().end());
  std::unordered_map<std::string, std::size_t> config_of_key;
  while (in.next()) {
    const auto& f = in.fields();
    // 1. The configuration: its config columns' key (runs_schema.hpp).
    auto [it, added] = config_of_key.try_emplace(header.config_key(f), t.configs.size());
    if (added) {
      Configuration& c = t.configs.emplace_back();
      for (const std::size_t col : config_cols) c.values.push_back(f[col]);
      c.end_counts.assign(t.end_reasons.size(), 0);
      c.metrics.resize(t.metric_names.size());
    }
    Configuration& config = t.configs[it->second];
    if (!t.config_of_run.try_emplace(f[run_key], it->second).second) {
      throw ConfigError(in.where(), "run_key " + f[run_key] + " appears twice");
    }
    ++config.n;
    std::uint64_t identity = kFnv1aBasis;
    for (const std::size_t c : identity_cols)
      identity = fnv1a(std::string_view("\x1f", 1), fnv1a(f[c], identity));
    config.distinct.insert(identity);
    // 2. End reason count (a reason this build does not know gets its own column).
    const std::string& reason = f[end_reason];
    if (reason.empty()) throw ConfigError(in.where(), "empty end_reason");
    const auto r = std::find(t.end_reasons.begin(), t.end_reasons.end(), reason);
    const auto r_index = static_cast<std::size_t>(r - t.end_reasons.begin());
    if (r == t.end_reasons.end()) {
      t.end_reasons.push_back(reason);
      for (auto& c : t.configs) c.end_counts.push_back(0);
    }
    ++config.end_counts[r_index];
    // 3. Metrics: every non-empty cell must be a number; NaN ("nan") counts as no value.
    for (std::size_t m = 0; m < metric_cols.size(); ++m) {
      const auto v = metric_value(f[metric_cols[m]], t.metric_names[m], in);
      if (v && !std::isnan(*v)) config.metrics[m].push_back(*v);
    }
  }
  return t;
}

/// Adds one run's samples (distance, area), in order, to its configuration's bands.
void add_run_progress(const std::vector<std::pair<double, double>>& samples, ProgressBands& bands) {
  for (std::size_t i = 0; i + 1 < samples.size(); ++i)
    bands.grid[samples[i].first].push_back(samples[i].second);
  const double last_grid =
      samples.size() > 1 ? samples[samples.size() - 2].first : -std::numeric_limits<double>::infinity();
  bands.finals.emplace_back(last_grid, samples.back().second);
  bands.max_final_m = std::max(bands.max_final_m, samples.back().first);
}

std::vector<ProgressBands> read_progress(const std::string& path, const RunsTable& runs) {
  std::vector<ProgressBands> bands(runs.configs.size());
  CsvReader in(path);
  const std::size_t run_key = in.require_column(kRunKeyColumn);
  const std::size_t distance = in.require_column(kProgressColumns[0]);
  const std::size_t area = in.require_column(kProgressColumns[1]);
  std::unordered_map<std::string, std::size_t> finished;  // run_key -> line of its first row
  std::string current;
  std::size_t current_line = 0;
  std::vector<std::pair<double, double>> samples;
  const auto flush = [&] {
    if (samples.empty()) return;
    const auto run = runs.config_of_run.find(current);
    // Rows of a run without a runs.csv row (torn or failed write) are not part of the results.
    if (run != runs.config_of_run.end()) add_run_progress(samples, bands[run->second]);
    finished.emplace(current, current_line);
    samples.clear();
  };
  while (in.next()) {
    const auto& f = in.fields();
    if (f[run_key] != current) {
      flush();
      if (const auto seen = finished.find(f[run_key]); seen != finished.end()) {
        throw ConfigError(in.where(), "rows of run " + f[run_key] +
                                          " are not contiguous (it started at line " +
                                          std::to_string(seen->second) + ")");
      }
      current = f[run_key];
      current_line = in.line();
    }
    const auto d = parse_number(f[distance]);
    const auto a = parse_number(f[area]);
    if (!d || !a || std::isnan(*d) || std::isnan(*a)) {
      throw ConfigError(in.where(), "distance_m and explored_area_m2 must be numbers, got '" + f[distance] +
                                        "', '" + f[area] + "'");
    }
    if (!samples.empty() && *d < samples.back().first) {
      throw ConfigError(in.where(), "distance_m decreases within run " + current);
    }
    samples.emplace_back(*d, *a);
  }
  flush();
  return bands;
}

void write_summary(const std::string& path, RunsTable& runs) {
  CsvOut out(path);
  std::vector<std::string> row{"config_id"};
  row.insert(row.end(), runs.config_names.begin(), runs.config_names.end());
  row.emplace_back("n");
  row.emplace_back("n_distinct");
  for (const auto& r : runs.end_reasons) row.push_back("end." + r);
  for (const auto& m : runs.metric_names) {
    for (const auto s : kStatisticNames) row.push_back(m + "." + std::string(s));
  }
  out.row(row);
  for (std::size_t id = 0; id < runs.configs.size(); ++id) {
    Configuration& c = runs.configs[id];
    row = {std::to_string(id)};
    row.insert(row.end(), c.values.begin(), c.values.end());
    row.push_back(std::to_string(c.n));
    row.push_back(std::to_string(c.distinct.size()));
    for (const auto count : c.end_counts) row.push_back(std::to_string(count));
    for (auto& values : c.metrics) {
      for (const double s : describe(values)) row.push_back(number_cell(s));
    }
    out.row(row);
  }
  out.close();
}

void write_progress_summary(const std::string& path, const std::string& source,
                            std::vector<ProgressBands>& bands) {
  CsvOut out(path);
  out.row({"config_id", "distance_m", "n", "explored_area_m2.mean", "explored_area_m2.q05",
           "explored_area_m2.q50", "explored_area_m2.q95"});
  std::vector<double> values;
  for (std::size_t id = 0; id < bands.size(); ++id) {
    ProgressBands& b = bands[id];
    if (b.finals.empty()) continue;
    // Runs by their last grid sample: those before a bin count with their final area.
    std::sort(b.finals.begin(), b.finals.end());
    const auto write_bin = [&](double distance_m) {
      const Statistics s = describe(values);
      if (values.size() != b.finals.size()) {
        throw ConfigError(source, "the runs of configuration " + std::to_string(id) +
                                      " are not sampled on a common distance grid (" +
                                      std::to_string(values.size()) + " of " +
                                      std::to_string(b.finals.size()) + " runs at " +
                                      format_number(distance_m) + " m)");
      }
      out.row({std::to_string(id), format_number(distance_m), std::to_string(values.size()),
               number_cell(s[0]), number_cell(s[3]), number_cell(s[5]), number_cell(s[7])});
    };
    std::size_t ended = 0;
    double last_bin = -std::numeric_limits<double>::infinity();
    for (const auto& [distance_m, sampled] : b.grid) {
      while (ended < b.finals.size() && b.finals[ended].first < distance_m) ++ended;
      values = sampled;
      for (std::size_t r = 0; r < ended; ++r) values.push_back(b.finals[r].second);
      write_bin(distance_m);
      last_bin = distance_m;
    }
    // Closing bin at the longest run's end: every run with its final area.
    if (b.max_final_m > last_bin + kSameDistanceM) {
      values.clear();
      for (const auto& f : b.finals) values.push_back(f.second);
      write_bin(b.max_final_m);
    }
  }
  out.close();
}

void write_best(const std::string& path, RunsTable& runs, const Objective& objective) {
  const auto m = std::find(runs.metric_names.begin(), runs.metric_names.end(), objective.column);
  if (m == runs.metric_names.end()) {
    throw ConfigError(runs.path + ":1",
                      "no column '" + std::string(objective.column) + "' for the objective");
  }
  const auto metric = static_cast<std::size_t>(m - runs.metric_names.begin());
  std::vector<Statistics> stats;
  std::vector<std::size_t> order;
  for (std::size_t id = 0; id < runs.configs.size(); ++id) {
    std::vector<double> values = runs.configs[id].metrics[metric];
    // Runs without a value as the worst (the objective's missing_is_worst); a quantile at one
    // of them has no value.
    if (objective.missing_is_worst) {
      const double worst = std::numeric_limits<double>::infinity();
      values.resize(static_cast<std::size_t>(runs.configs[id].n),
                    objective.direction == Direction::Maximize ? -worst : worst);
    }
    stats.push_back(describe(values));
    for (double& v : stats.back()) {
      if (std::isinf(v)) v = std::numeric_limits<double>::quiet_NaN();
    }
    order.push_back(id);
  }
  // Median ascending (descending for area per metre); no value last; ties by configuration order.
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const double x = stats[a][5];
    const double y = stats[b][5];
    if (std::isnan(x) || std::isnan(y)) return !std::isnan(x) && std::isnan(y);
    return objective.direction == Direction::Maximize ? x > y : x < y;
  });
  CsvOut out(path);
  const std::string name(objective.name);
  std::vector<std::string> row{"rank", "config_id", "n", name + ".median", name + ".q05", name + ".q95"};
  row.insert(row.end(), runs.config_names.begin(), runs.config_names.end());
  out.row(row);
  for (std::size_t rank = 0; rank < order.size(); ++rank) {
    const std::size_t id = order[rank];
    const Configuration& c = runs.configs[id];
    row = {std::to_string(rank + 1),  std::to_string(id),        std::to_string(c.n),
           number_cell(stats[id][5]), number_cell(stats[id][3]), number_cell(stats[id][7])};
    row.insert(row.end(), c.values.begin(), c.values.end());
    out.row(row);
  }
  out.close();
}

/// The objective: the option, else the manifest's, else the default.
const Objective& choose_objective(const std::string& dir, const std::string& requested) {
  std::string name = requested;
  std::string where = "--objective";
  const std::string manifest_path = dir + "/manifest.json";
  if (name.empty() && std::filesystem::exists(manifest_path)) {
    const auto manifest = parse_json_or_discard(read_file(manifest_path).value_or(""));
    if (manifest.is_discarded()) throw ConfigError(manifest_path, "not valid JSON");
    // The sweep file's choice, else the runner's resolved one (manifest.hpp).
    for (const char* key : {"/sweep/output/objective", "/objective"}) {
      const auto pointer = nlohmann::json::json_pointer(key);
      if (manifest.contains(pointer) && manifest.at(pointer).is_string()) {
        name = manifest.at(pointer).get<std::string>();
        where = manifest_path + ": " + key;
        break;
      }
    }
  }
  if (name.empty()) return kObjectives[0];
  return require_objective(name, where);
}

}  // namespace

void aggregate(const std::string& dir, const AggregateOptions& options) {
  const Objective& objective = choose_objective(dir, options.objective);
  RunsTable runs = read_runs(dir + "/runs.csv");
  std::vector<ProgressBands> bands = read_progress(dir + "/progress.csv", runs);
  write_best(dir + "/best.csv", runs, objective);
  write_progress_summary(dir + "/progress_summary.csv", dir + "/progress.csv", bands);
  write_summary(dir + "/summary.csv", runs);
}

}  // namespace report
}  // namespace fsweep
