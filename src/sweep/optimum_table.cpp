/// @file optimum_table.cpp
/// The offline optimum of a sweep's competitive maps (optimum_table.hpp).

#include "sweep/optimum_table.hpp"

#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <mutex>
#include <optional>
#include <set>
#include <vector>

#include "core/config_error.hpp"
#include "core/csv_format.hpp"
#include "core/csv_reader.hpp"
#include "core/files.hpp"
#include "core/random.hpp"
#include "optimum/optimum.hpp"
#include "world/world_map.hpp"

namespace fsweep {
inline namespace sweep {
namespace {

/// optima.csv's columns; the first three are the key.
constexpr const char* kOptimumColumns[] = {
    "solver",  "map_hash", "robot",        "lower_m",      "upper_m",          "exact", "error",
    "targets", "nodes",    "lower_method", "upper_method", "exact_expansions", "time_s"};
constexpr std::size_t kOptimumColumnCount = std::size(kOptimumColumns);

/// The entries of optima.csv of `solver`, by key; a file that does not read is named on stderr
/// and counts as empty (it is rewritten).
std::map<std::string, OptimumBounds> read_cache(const std::string& path, const std::string& solver) {
  std::map<std::string, OptimumBounds> out;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return out;
  try {
    CsvReader in(path);
    if (in.header() != std::vector<std::string>(std::begin(kOptimumColumns), std::end(kOptimumColumns)))
      throw ConfigError(path + ":1", "not the columns of this build's optima.csv");
    while (in.next()) {
      const std::vector<std::string>& f = in.fields();
      if (f.size() != kOptimumColumnCount) throw ConfigError(in.where(), "wrong number of fields");
      if (f[0] != solver) continue;
      OptimumBounds b;
      const auto number = [&](std::size_t c) {
        const auto v = parse_number(f[c]);
        if (!v)
          throw ConfigError(in.where(), std::string("column '") + kOptimumColumns[c] + "': not a number");
        return *v;
      };
      b.error = f[6];
      if (b.error.empty()) {
        b.lower_m = number(3);
        b.upper_m = number(4);
        b.exact = f[5] == "1";
      }
      b.targets = static_cast<int>(number(7));
      b.nodes = static_cast<int>(number(8));
      b.lower_method = f[9];
      b.upper_method = f[10];
      b.exact_expansions = static_cast<long>(number(11));
      b.time_s = number(12);
      out[f[1] + '\n' + f[2]] = std::move(b);
    }
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "fsweep: warning: %s: %s; its optima are computed again\n", path.c_str(), e.what());
    out.clear();
  }
  return out;
}

/// Writes `entries` (of `solver`) to `path`, sorted by key, through a temp file and rename.
void write_cache(const std::string& path, const std::string& solver,
                 const std::map<std::string, OptimumBounds>& entries) {
  std::string text =
      csv_record(std::vector<std::string>(std::begin(kOptimumColumns), std::end(kOptimumColumns))) + '\n';
  for (const auto& [key, b] : entries) {
    const std::size_t split = key.find('\n');
    const bool ok = b.error.empty();
    text +=
        csv_record({solver, key.substr(0, split), key.substr(split + 1), ok ? format_number(b.lower_m) : "",
                    ok ? format_number(b.upper_m) : "", ok ? (b.exact ? "1" : "0") : "", b.error,
                    std::to_string(b.targets), std::to_string(b.nodes), b.lower_method, b.upper_method,
                    std::to_string(b.exact_expansions), format_number(b.time_s)}) +
        '\n';
  }
  write_file_atomically(path, text);
}

/// A number cell of a bound: empty when not finite.
std::string bound_cell(double v) { return std::isfinite(v) ? format_number(v) : std::string(); }

}  // namespace

std::string optimum_solver_version() {
  const OptimumOptions o;
  return "optimum-3 witnesses=" + std::to_string(o.lower.max_witnesses) +
         " ascent=" + std::to_string(o.lower.ascent_steps) +
         " held_karp=" + std::to_string(o.lower.held_karp_groups) +
         " swaps=" + std::to_string(o.lower.witness_swaps) + " passes=" + std::to_string(o.route.max_passes) +
         " relocations=" + std::to_string(o.route.max_relocations) +
         " restarts=" + std::to_string(o.route.restarts) + " noise=" + format_number(o.route.restart_noise) +
         " restart_work=" + std::to_string(o.route.restart_work) +
         " expansions=" + std::to_string(o.exact.max_expansions);
}

std::string optimum_key(const RunSpec& spec) {
  nlohmann::json robot = spec.robot;
  if (!spec.robot.dock) robot["dock"] = nlohmann::json{spec.map->start.x, spec.map->start.y};
  // The offline sensor is noiseless: runs that differ only in their misses share one optimum.
  if (robot.contains("sensor")) robot["sensor"].erase("miss_probability");
  return hex64(content_hash(*spec.map)) + '\n' + robot.dump();
}

OptimumBounds compute_optimum(const RunSpec& spec) {
  OptimumBounds b;
  try {
    const OptimumResult r = solve_optimum(spec, OptimumOptions{});  // budgets only, no deadline
    b.lower_m = r.lower_m;
    b.upper_m = r.upper_m;
    b.exact = r.exact;
    b.targets = r.targets;
    b.nodes = r.nodes;
    b.lower_method = r.lower_method;
    b.upper_method = r.upper_method;
    b.exact_expansions = r.exact_expansions;
    b.time_s = r.time_s;
  } catch (const ConfigError& e) {
    b.error = e.what();
  }
  return b;
}

const OptimumBounds* OptimumTable::find(const RunSpec& spec) const {
  const auto it = entries_.find(optimum_key(spec));
  return it == entries_.end() ? nullptr : &it->second;
}

OptimumTable OptimumTable::prepare(const SweepPlan& plan, const std::string& dir, std::uint64_t shard_index,
                                   std::uint64_t shard_count, int threads, OptimumReport& report) {
  OptimumTable table;
  report = {};
  if (!plan.competitive() || plan.run_count() == 0) return table;
  // 1. The keys the shard's runs need: per competitive map and robot variant (and repetition,
  //    for a random start, which the run seed draws), one run of the shard. Run index
  //    (((map * S + s) * P + p) * R + robot) * K + k (sweep_plan.hpp): the residues mod n of
  //    the other axes repeat after n values, so n of each suffice.
  const auto axes = plan.axes();
  const std::uint64_t sp = axes.at(1).second * axes.at(2).second;
  const std::uint64_t robots = axes.at(3).second;
  const std::uint64_t reps = axes.at(4).second;
  const std::uint64_t n = shard_count;
  std::vector<RunSpec> specs;
  std::set<std::string> keys;
  const auto add = [&](std::uint64_t index) {
    RunSpec spec = plan.run_spec(index);
    if (keys.insert(optimum_key(spec)).second) specs.push_back(std::move(spec));
  };
  for (std::uint64_t m = 0; m < plan.maps().size(); ++m) {
    if (!plan.maps()[m].competitive) continue;
    const bool per_repetition = plan.maps()[m].start_regions != nullptr;
    for (std::uint64_t r = 0; r < robots; ++r) {
      const auto find_run = [&](std::uint64_t k_from, std::uint64_t k_to) -> std::optional<std::uint64_t> {
        for (std::uint64_t j = 0; j < std::min(sp, n); ++j) {
          for (std::uint64_t k = k_from; k < k_to; ++k) {
            const std::uint64_t index = ((m * sp + j) * robots + r) * reps + k;
            if (index % n == shard_index) return index;
          }
        }
        return std::nullopt;
      };
      if (per_repetition) {
        for (std::uint64_t k = 0; k < reps; ++k) {
          if (const auto index = find_run(k, k + 1)) add(*index);
        }
      } else if (const auto index = find_run(0, std::min(reps, n))) {
        add(*index);
      }
    }
  }
  report.needed = specs.size();
  // 2. The cache, then the missing keys.
  const std::string solver = optimum_solver_version();
  const std::string path = dir + "/" + kOptimaFile;
  std::map<std::string, OptimumBounds> all = read_cache(path, solver);
  std::vector<const RunSpec*> missing;
  for (const RunSpec& spec : specs) {
    const std::string key = optimum_key(spec);
    if (const auto it = all.find(key); it != all.end()) {
      table.entries_.emplace(key, it->second);
      ++report.cached;
    } else {
      missing.push_back(&spec);
    }
  }
  const auto start = std::chrono::steady_clock::now();
  if (!missing.empty()) {
    std::mutex mutex;
    tbb::task_arena arena(std::max(1, threads));
    arena.execute([&] {
      tbb::parallel_for(std::size_t{0}, missing.size(), [&](std::size_t i) {
        OptimumBounds b = compute_optimum(*missing[i]);
        const std::string key = optimum_key(*missing[i]);
        const std::lock_guard<std::mutex> lock(mutex);
        table.entries_.emplace(key, b);
        all[key] = std::move(b);
        write_cache(path, solver, all);  // a kill keeps what was computed
      });
    });
    report.computed = missing.size();
  } else if (!std::filesystem::exists(path)) {
    write_cache(path, solver, all);
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return table;
}

std::size_t merge_optima(const std::string& dir, const std::vector<std::string>& shard_dirs) {
  const std::string solver = optimum_solver_version();
  std::map<std::string, OptimumBounds> all;
  bool any = false;
  for (const std::string& shard : shard_dirs) {
    const std::string path = shard + "/" + kOptimaFile;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) continue;
    any = true;
    for (auto& [key, b] : read_cache(path, solver)) all.emplace(key, std::move(b));  // the same for any shard
  }
  if (any) write_cache(dir + "/" + kOptimaFile, solver, all);
  return all.size();
}

std::vector<std::string> competitive_cells(const SweepMap& map, const OptimumBounds* optimum,
                                           const RunResult* result) {
  std::vector<std::string> cells(kCompetitiveColumns.size());
  std::string& note = cells[5];
  if (!map.competitive) {
    note = kNotCompetitiveNote;
    return cells;
  }
  if (optimum == nullptr) {
    note = "no optimum";
    return cells;
  }
  const OptimumBounds& b = *optimum;
  if (!b.error.empty()) {
    note = "no optimum: " + b.error;
    return cells;
  }
  cells[0] = bound_cell(b.lower_m);
  cells[1] = bound_cell(b.upper_m);
  cells[2] = b.exact ? "1" : "0";
  if (result == nullptr) {
    note = "end error";
    return cells;
  }
  const RunMetrics& m = result->metrics;
  if (result->end != EndReason::Complete) {
    note = "end " + std::string(to_string(result->end));
    return cells;
  }
  if (!(m.completeness >= 1.0)) {
    // Cut, not rounded, so that a completeness below 1 never reads "1".
    note = "end complete but completeness " + format_number(std::floor(m.completeness * 1e4) / 1e4);
    return cells;
  }
  const double d = m.distance_to_final_coverage_m;
  if (b.upper_m == 0.0) {
    note = "optimum 0 m (the start reveals every cell)";
    return cells;
  }
  if (std::isfinite(b.upper_m)) cells[3] = format_number(d / b.upper_m);
  if (std::isfinite(b.lower_m) && b.lower_m > 0.0) cells[4] = format_number(d / b.lower_m);
  if (!std::isfinite(b.upper_m)) {
    note = "no upper bound found";
  } else if (!(b.lower_m > 0.0)) {
    note = "lower bound 0 m";
  } else if (d < b.lower_m * (1.0 - 1e-9)) {
    note = "lower bound above this complete run (a solver bug: please report)";
  }
  return cells;
}

}  // namespace sweep
}  // namespace fsweep
