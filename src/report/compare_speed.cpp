#include "report/compare_speed.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <utility>

#include "core/config_error.hpp"
#include "core/csv_format.hpp"
#include "core/files.hpp"
#include "core/json_text.hpp"

namespace fsweep {
inline namespace report {
namespace {

using nlohmann::json;

/// The whole JSON file; ConfigError naming it when missing or malformed. `benchmark`: Google
/// Benchmark's output, whose non-finite numbers (NaN, Infinity) are read as null.
json read_json_file(const std::string& path, bool benchmark = false) {
  const std::optional<std::string> text = read_file(path);
  if (!text) throw ConfigError(path, "cannot be read (missing?)");
  try {
    return parse_json_bounded(benchmark ? null_non_finite_words(*text) : *text, path);
  } catch (const json::parse_error& e) {
    throw ConfigError(path, std::string("not valid JSON: ") + e.what());
  }
}

std::optional<std::string> string_at(const json& j, const char* key) {
  if (!j.contains(key) || !j[key].is_string()) return std::nullopt;
  return j[key].get<std::string>();
}

std::optional<double> number_at(const json& j, const char* key) {
  if (!j.contains(key) || !j[key].is_number()) return std::nullopt;
  return j[key].get<double>();
}

/// Nanoseconds per `unit` of Google Benchmark's time_unit.
std::optional<double> ns_per_unit(const std::string& unit) {
  if (unit == "ns") return 1.0;
  if (unit == "us") return 1e3;
  if (unit == "ms") return 1e6;
  if (unit == "s") return 1e9;
  return std::nullopt;
}

void add_difference(std::vector<std::string>& out, const std::string& what,
                    const std::optional<std::string>& base, const std::optional<std::string>& current) {
  if (base && current && *base != *current) {
    out.push_back(what + ": '" + *base + "' (baseline) vs '" + *current + "' (new)");
  }
}

std::optional<std::string> number_string(const std::optional<double>& v) {
  if (!v) return std::nullopt;
  return format_number(*v);
}

}  // namespace

ManifestFacts read_manifest_facts(const std::string& path) {
  const json j = read_json_file(path);
  if (!j.is_object()) throw ConfigError(path, "expected a JSON object (a sweep manifest)");
  ManifestFacts m;
  m.path = path;
  m.sweep_hash = string_at(j, "sweep_hash");
  m.host = string_at(j, "host");
  m.cpu_model = string_at(j, "cpu_model");
  m.status = string_at(j, "status");
  if (j.contains("threads") && j["threads"].is_number_integer()) m.threads = j["threads"].get<long long>();
  const auto wall_s = number_at(j, "wall_s");
  m.wall_s = wall_s;
  std::optional<double> ran;
  if (j.contains("runs") && j["runs"].is_object()) ran = number_at(j["runs"], "ran");
  // A manifest merged from shards (merge.hpp) has the longest shard's wall time for runs spread
  // over several processes: no per-run time of one process, so its throughput is not judged.
  const bool merged = j.contains(json::json_pointer("/shard/merged_from"));
  if (!merged && wall_s && ran && *wall_s > 0.0 && *ran > 0.0) m.seconds_per_run = *wall_s / *ran;
  return m;
}

std::optional<BenchFile> read_bench_file(const std::string& path) {
  if (!std::filesystem::exists(path)) return std::nullopt;
  const json j = read_json_file(path, true);
  if (!j.is_object() || !j.contains("benchmarks") || !j["benchmarks"].is_array()) {
    throw ConfigError(path,
                      "expected Google Benchmark's JSON output (an object with a \"benchmarks\" array)");
  }
  BenchFile b;
  b.path = path;
  if (j.contains("context") && j["context"].is_object()) {
    const json& c = j["context"];
    b.host_name = string_at(c, "host_name");
    b.num_cpus = number_at(c, "num_cpus");
    b.mhz_per_cpu = number_at(c, "mhz_per_cpu");
  }
  // 1. Per benchmark: the median aggregate, the iteration rows, errors.
  struct Acc {
    std::optional<double> median_ns;
    double sum_ns = 0.0;
    std::size_t iterations = 0;
    bool error = false;
  };
  std::vector<std::string> order;
  std::map<std::string, Acc> acc;
  const json& list = j["benchmarks"];
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& e = list[i];
    const std::string where = path + ": /benchmarks/" + std::to_string(i);
    if (!e.is_object()) throw ConfigError(where, "expected an object");
    auto name = string_at(e, "run_name");
    if (!name) name = string_at(e, "name");
    if (!name) throw ConfigError(where, "a benchmark needs a string \"name\" (or \"run_name\")");
    auto [it, added] = acc.try_emplace(*name);
    if (added) order.push_back(*name);
    if (e.value("error_occurred", false)) {
      it->second.error = true;
      continue;
    }
    const std::string run_type = e.value("run_type", std::string("iteration"));
    if (run_type == "aggregate" && e.value("aggregate_name", std::string()) != "median") continue;
    const auto real_time = number_at(e, "real_time");
    if (!real_time) throw ConfigError(where + "/real_time", "expected a number");
    const std::string unit = e.value("time_unit", std::string("ns"));
    const auto scale = ns_per_unit(unit);
    if (!scale) throw ConfigError(where + "/time_unit", "'" + unit + "' is not one of ns, us, ms, s");
    if (run_type == "aggregate") {
      it->second.median_ns = *real_time * *scale;
    } else {
      it->second.sum_ns += *real_time * *scale;
      ++it->second.iterations;
    }
  }
  // 2. One time each (a benchmark with neither median nor iterations had only errors).
  for (const std::string& name : order) {
    const Acc& a = acc[name];
    BenchTime t;
    t.name = name;
    t.error = a.error;
    if (a.median_ns) {
      t.real_time_ns = *a.median_ns;
    } else if (a.iterations > 0) {
      t.real_time_ns = a.sum_ns / static_cast<double>(a.iterations);
    } else {
      t.error = true;
    }
    b.times.push_back(t);
  }
  return b;
}

std::vector<std::string> machine_differences(const ManifestFacts& baseline, const ManifestFacts& current,
                                             const BenchFile* baseline_bench,
                                             const BenchFile* current_bench) {
  std::vector<std::string> out;
  add_difference(out, "manifest host", baseline.host, current.host);
  add_difference(out, "manifest cpu_model", baseline.cpu_model, current.cpu_model);
  if (baseline_bench && current_bench) {
    add_difference(out, "bench.json host_name", baseline_bench->host_name, current_bench->host_name);
    add_difference(out, "bench.json num_cpus", number_string(baseline_bench->num_cpus),
                   number_string(current_bench->num_cpus));
    add_difference(out, "bench.json mhz_per_cpu", number_string(baseline_bench->mhz_per_cpu),
                   number_string(current_bench->mhz_per_cpu));
  }
  return out;
}

CompareCheck time_ratio_check(std::string kind, std::string name, std::string metric,
                              std::optional<double> baseline, std::optional<double> current, double tolerance,
                              bool may_fail) {
  CompareCheck c;
  c.kind = std::move(kind);
  c.name = std::move(name);
  c.metric = std::move(metric);
  c.tolerance = tolerance;
  if (baseline) c.baseline = format_number(*baseline);
  if (current) c.current = format_number(*current);
  if (!baseline || !current || !(*baseline > 0.0) || !(*current > 0.0)) {
    c.status = CheckStatus::NotJudged;
    return c;
  }
  const double ratio = *current / *baseline;
  c.ratio = ratio;
  if (ratio > 1.0 + tolerance) {
    c.status = CheckStatus::Slower;
    c.failure = may_fail;
  } else if (ratio < 1.0 / (1.0 + tolerance)) {
    c.status = CheckStatus::Faster;
  } else {
    c.status = CheckStatus::WithinTolerance;
  }
  return c;
}

void add_sweep_speed_checks(CompareReport& report, const ManifestFacts& baseline,
                            const ManifestFacts& current, const BenchFile* baseline_bench,
                            const BenchFile* current_bench, const CompareOptions& options) {
  const bool machine_ok = report.same_machine || options.strict_speed;
  // 1. Sweep throughput (seconds per run, so that > 1 is slower like every ratio here).
  const bool same_threads = !baseline.threads || !current.threads || *baseline.threads == *current.threads;
  if (!same_threads) {
    report.warnings.push_back("manifests: threads " + std::to_string(*baseline.threads) + " (baseline) vs " +
                              std::to_string(*current.threads) +
                              " (new): the sweep throughput is informational unless --strict-speed");
  }
  CompareCheck sweep =
      time_ratio_check("speed", "sweep", "seconds_per_run", baseline.seconds_per_run, current.seconds_per_run,
                       options.speed_tolerance, options.strict_speed || (machine_ok && same_threads));
  if (sweep.status != CheckStatus::NotJudged && baseline.wall_s &&
      *baseline.wall_s < options.min_judged_sweep_wall_s) {
    // A sweep of a few seconds times mostly the process start and whatever else the machine runs.
    sweep.status = CheckStatus::NotJudged;
    sweep.failure = false;
    char why[160];
    std::snprintf(why, sizeof(why),
                  "the baseline sweep took %.3g s, below the %.3g s that are judged on speed",
                  *baseline.wall_s, options.min_judged_sweep_wall_s);
    report.notes.emplace_back(why);
  }
  report.checks.push_back(sweep);
  // 2. Micro-benchmarks, baseline order, then those only in NEW.
  if (!baseline_bench && !current_bench) return;
  if (!baseline_bench || !current_bench) {
    report.warnings.push_back(std::string("bench.json only in ") + (baseline_bench ? "the baseline" : "NEW") +
                              ": micro-benchmarks not compared");
    return;
  }
  std::map<std::string, const BenchTime*> current_times;
  for (const BenchTime& t : current_bench->times) current_times.emplace(t.name, &t);
  std::map<std::string, bool> seen;
  for (const BenchTime& b : baseline_bench->times) {
    seen[b.name] = true;
    const auto it = current_times.find(b.name);
    const std::optional<double> base_ns = b.error ? std::nullopt : std::optional<double>(b.real_time_ns);
    if (it == current_times.end() || it->second->error) {
      CompareCheck c;
      c.kind = "bench";
      c.name = b.name;
      c.metric = "real_time_ns";
      if (base_ns) c.baseline = format_number(*base_ns);
      c.current = it == current_times.end() ? "" : "error";
      c.status = CheckStatus::Missing;
      c.failure = true;
      report.checks.push_back(c);
      continue;
    }
    report.checks.push_back(time_ratio_check("bench", b.name, "real_time_ns", base_ns,
                                             it->second->real_time_ns, options.speed_tolerance, machine_ok));
  }
  for (const BenchTime& t : current_bench->times) {
    if (seen.count(t.name) != 0) continue;
    CompareCheck c;
    c.kind = "bench";
    c.name = t.name;
    c.metric = "real_time_ns";
    c.current = t.error ? "error" : format_number(t.real_time_ns);
    c.status = CheckStatus::New;
    report.checks.push_back(c);
  }
}

}  // namespace report
}  // namespace fsweep
