#include "sweep/weight_search_runner.hpp"

#include <oneapi/tbb/info.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/config_error.hpp"
#include "core/csv_format.hpp"
#include "core/csv_reader.hpp"
#include "core/files.hpp"
#include "core/json_text.hpp"
#include "core/random.hpp"
#include "core/statistics.hpp"
#include "report/runs_schema.hpp"
#include "report/search_schema.hpp"
#include "sim/heuristics.hpp"
#include "sweep/manifest.hpp"
#include "sweep/progress_meter.hpp"
#include "sweep/sweep_table.hpp"
#include "weightsearch/exact_search.hpp"
#include "weightsearch/weight_grid.hpp"

namespace fsweep {
inline namespace sweep {
namespace {

using nlohmann::json;
using Point = std::array<int, WeightGrid::kMaxWeights>;

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

/// One behaviour, formatted: its metric cells per instance and the numbers they hold.
struct Found {
  Behaviour behaviour;
  /// Per instance, the metric columns (runs.csv's, plus optimal_distance_m and
  /// competitive_ratio; effort metrics empty).
  std::vector<Columns> cells;
  /// Per instance and metric column, the value (NaN: none).
  std::vector<std::vector<double>> values;
  double objective = kNoValue;
  /// Which of the search's `rank` vectors it holds (positions in WeightSearch::rank), noted
  /// when it was admitted (SearchWriter::admit()), so that its region need not be kept.
  std::vector<std::size_t> ranked;
};

/// How many distinct outcomes `found` holds: behaviours whose metric cells (end reason and detail,
/// every metric but the effort ones, on every instance) are all equal count once. Different
/// decision sequences can end in the same outcome (the same distance, coverage and counts).
std::size_t distinct_outcomes(const std::vector<Found>& found) {
  std::set<std::vector<std::string>> outcomes;
  for (const Found& f : found) {
    std::vector<std::string> key;
    for (const Columns& cells : f.cells) {
      for (const auto& [name, cell] : cells) {
        if (!is_effort_column(name)) key.push_back(cell);
      }
    }
    outcomes.insert(std::move(key));
  }
  return outcomes.size();
}

/// What a search's journal holds: its behaviours, and the subtrees of its region tree whose
/// every leaf had finished or been pruned (by id, SubtreeJournal).
struct Journal {
  std::vector<Found> found;
  std::unordered_map<std::uint64_t, SubtreeTally> done;
};

/// A metric cell's number (NaN: empty, or not a number).
double number_of(const std::string& cell) { return parse_number(cell).value_or(kNoValue); }

/// Formats one instance's run of a behaviour.
Columns instance_cells(const RunResult& result, const SweepMap& map, const RunSpec& spec) {
  Columns cells = metric_columns(result);
  for (auto& [name, value] : cells) {
    if (is_effort_column(name)) value.clear();
  }
  const double optimum = optimal_distance_m(map, spec);
  cells.emplace_back(kSweepMetricColumns[0], number_cell(optimum));
  cells.emplace_back(kSweepMetricColumns[1], std::isnan(optimum)
                                                 ? std::string()
                                                 : format_number(result.metrics.distance_m / optimum));
  return cells;
}

/// The value of metric column `column` of a run (NaN: none).
double metric_value(const RunResult& result, std::string_view column) {
  for (const auto& [name, cell] : metric_columns(result)) {
    if (name == column) return number_of(cell);
  }
  throw std::logic_error("no metric column " + std::string(column));
}

/// A behaviour's objective: the mean over its instances' runs, summed in instance order.
double class_objective(const std::vector<RunResult>& results, const Objective& objective) {
  double sum = 0.0;
  for (const RunResult& r : results) sum += metric_value(r, objective.column);
  return sum / static_cast<double>(results.size());
}

/// Branch and bound's admissible lower bound of class_objective() (signed: for a maximised
/// objective, of its negation) over the behaviours that continue `sims`. Both minimised
/// objectives only grow as a run goes on, so their values so far bound them, summed in the same
/// order (rounding is monotone):
/// - distance_to_final_coverage_m: the distance at the last reveal so far (the final coverage
///   is reached at a reveal no earlier than it);
/// - energy: the energy used so far (every step costs energy >= 0).
/// Nothing is known of area_per_metre: -infinity (no pruning).
double class_lower_bound(std::span<const Simulation> sims, const Objective& objective) {
  double sum = 0.0;
  for (const Simulation& s : sims) {
    const RunMetrics& m = s.metrics_so_far();
    if (objective.column == "distance_to_final_coverage_m") {
      sum += m.distance_to_final_coverage_m;
    } else if (objective.column == "energy") {
      sum += m.energy;
    } else {
      return -std::numeric_limits<double>::infinity();
    }
  }
  return sum / static_cast<double>(sims.size());
}

/// Better objective first; no value last.
bool better(double a, double b, Direction direction) {
  if (std::isnan(a) || std::isnan(b)) return !std::isnan(a) && std::isnan(b);
  return direction == Direction::Minimize ? a < b : a > b;
}

/// A planner as tables show it: its name, and its parameters when given.
std::string planner_label(const SweepPlanner& p) {
  return p.params.is_null() ? p.name : p.name + " " + p.params.dump();
}

/// Heat maps over weight pairs, filled one behaviour at a time (SearchWriter::admit()): per
/// pair of weights (a, b) and pair of their values, the best objective among the behaviours
/// with a vector there, and of the behaviours with that objective the smallest representative.
/// Behaviour ids follow the representatives, so that is the smallest id: what a walk over
/// every behaviour in id order, keeping the first of the best, gives.
class HeatMaps {
 public:
  /// `wanted`: false for a search without heat maps (mode best), which then holds none.
  HeatMaps(const WeightGrid& grid, Direction direction, bool wanted) : grid_(grid), direction_(direction) {
    const int w = wanted ? grid.weights() : 0;
    for (int a = 0; a < w; ++a) {
      for (int b = a + 1; b < w; ++b) {
        const std::size_t cells = grid.values(a).size() * grid.values(b).size();
        maps_.push_back({a, b, std::vector<double>(cells, kNoValue), std::vector<Point>(cells),
                         std::vector<std::uint8_t>(cells, 0)});
      }
    }
  }

  /// Adds a behaviour: its region, objective and representative.
  void add(const WeightRegion& region, double objective, const Point& representative) {
    for (Map& m : maps_) {
      const std::size_t nb = grid_.values(m.b).size();
      grid_.for_each_projection(region, m.a, m.b, [&](int ia, int ib) {
        const std::size_t cell = static_cast<std::size_t>(ia) * nb + static_cast<std::size_t>(ib);
        const bool take = m.set[cell] == 0 || better(objective, m.best[cell], direction_) ||
                          (!better(m.best[cell], objective, direction_) && representative < m.owner[cell]);
        if (!take) return;
        m.set[cell] = 1;
        m.best[cell] = objective;
        m.owner[cell] = representative;
      });
    }
  }

  /// One map per pair a < b, in order: `best` and `owner` (a representative) per cell
  /// (value of a) * (values of b) + (value of b); `set`: whether any behaviour projects there.
  struct Map {
    int a = 0;
    int b = 0;
    std::vector<double> best;
    std::vector<Point> owner;
    std::vector<std::uint8_t> set;
  };
  [[nodiscard]] const std::vector<Map>& maps() const { return maps_; }

 private:
  const WeightGrid& grid_;
  Direction direction_;
  std::vector<Map> maps_;
};

/// What one search (or one shard's, or the shards' merged) found.
struct Searched {
  std::vector<Found> found;
  /// Of them, read from the journal of a killed search.
  std::size_t resumed = 0;
  ExactSearchStats stats;
  double wall_s = 0.0;
};

/// Everything one search writes, as text rows (each with its newline).
// NOLINTNEXTLINE(bugprone-exception-escape): false positive inside nlohmann::json's noexcept move
struct SearchRows {
  std::string behaviours;
  std::string summary;
  std::string best;
  std::string ranks;
  std::string heatmaps;
  std::string vectors;
  json record;
};

class SearchWriter {
 public:
  SearchWriter(const SweepPlan& plan, const SearchUnit& unit, std::size_t id, const Objective& objective,
               std::string out_dir)
      : out_dir_(std::move(out_dir)),
        plan_(plan),
        unit_(unit),
        id_(std::to_string(id)),
        search_(*plan.strategies().at(unit.entry).search),
        grid_(search_.values),
        objective_(objective),
        heat_(grid_, objective.direction, search_.mode == WeightSearch::Mode::All) {
    for (const std::vector<double>& vector : search_.rank) {
      Point at{};
      for (int k = 0; k < grid_.weights(); ++k) {
        const auto values = grid_.values(k);
        at[static_cast<std::size_t>(k)] = static_cast<int>(
            std::lower_bound(values.begin(), values.end(), vector[static_cast<std::size_t>(k)]) -
            values.begin());
      }
      rank_points_.push_back(at);
    }
  }
  // Its heat maps refer to its grid.
  SearchWriter(const SearchWriter&) = delete;
  SearchWriter& operator=(const SearchWriter&) = delete;

  /// Searches `root` (everything, or a shard: WeightGrid::shard()) and formats what it finds.
  /// `on_vectors(n)`: n more vectors resolved. Every behaviour found and every finished subtree
  /// goes to the journal at once; those a killed search of the same key journaled are kept and
  /// skipped (mode best: the best journaled behaviour is the incumbent to beat).
  Searched search(int threads, const std::function<void(std::uint64_t)>& on_vectors, const WeightRegion& root,
                  const std::atomic<bool>* stop) {
    const std::vector<RunSpec> specs = instance_specs();
    const auto start = std::chrono::steady_clock::now();
    Searched out;
    std::vector<Found>& found = out.found;
    const std::string key = unit_key(specs.size());
    Journal journaled = read_journal(key, out_dir_, true, true);
    found = std::move(journaled.found);
    // The subtrees the journal holds finished: its nodes, and its behaviours as leaves.
    const std::uint64_t root_id = subtree_root(root);
    std::unordered_map<std::uint64_t, SubtreeTally>& done = journaled.done;
    const double sign = direction_sign();
    double incumbent = std::numeric_limits<double>::infinity();
    for (const Found& f : found) {
      SubtreeTally leaf;
      leaf.vectors = f.behaviour.vectors;
      leaf.behaviours = 1;
      done.emplace(subtree_of(root_id, f.behaviour.choices), leaf);
      if (!std::isnan(f.objective)) incumbent = std::min(incumbent, sign * f.objective);
    }
    out.resumed = found.size();
    std::ofstream journal(journal_path(out_dir_), std::ios::app | std::ios::binary);
    if (!journal) throw ConfigError(journal_path(out_dir_), "cannot open for appending");
    const auto append = [&](const std::string& line) {
      journal << line << '\n';
      journal.flush();
      if (!journal) throw ConfigError(journal_path(out_dir_), "write error");
    };
    SubtreeJournal subtrees;
    subtrees.done = &done;
    subtrees.on_done = [&](std::uint64_t id, const SubtreeTally& t) { append(done_line(key, id, t)); };
    subtrees.on_skipped = on_vectors;
    const auto keep = [&](Behaviour&& b) {
      on_vectors(b.vectors);
      Found f;
      f.behaviour = std::move(b);
      for (std::size_t i = 0; i < specs.size(); ++i) {
        f.cells.push_back(instance_cells(f.behaviour.results[i], instance_map(i), specs[i]));
      }
      f.behaviour.results.clear();  // formatted; the runs' trajectories are not kept
      f.objective = objective_of(f.cells);
      append(journal_line(key, f));
      admit(f);
      found.push_back(std::move(f));
    };
    if (search_.mode == WeightSearch::Mode::All) {
      out.stats = exact_search(specs, grid_, threads, keep, nullptr, &root, &subtrees, stop);
    } else {
      BranchAndBound bnb;
      bnb.objective = [&](const std::vector<RunResult>& results) {
        return sign * class_objective(results, objective_);
      };
      bnb.lower_bound = [&](std::span<const Simulation> sims) { return class_lower_bound(sims, objective_); };
      bnb.on_pruned = on_vectors;
      bnb.incumbent = incumbent;
      out.stats = exact_search(specs, grid_, threads, keep, &bnb, &root, &subtrees, stop);
    }
    out.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
  }

  /// Takes a behaviour of the whole grid (one search's, or one the shards' parts make up) into
  /// mode all's running results: the rank vectors it holds and its heat-map cells. Its region is
  /// then dropped unless vectors.csv needs it: the full [0, 250]^4's behaviours would hold tens
  /// of gigabytes of regions, these results a few megabytes.
  void admit(Found& f) {
    if (search_.mode != WeightSearch::Mode::All) return;
    for (std::size_t r = 0; r < rank_points_.size(); ++r) {
      if (grid_.contains(f.behaviour.region, rank_points_[r])) f.ranked.push_back(r);
    }
    heat_.add(f.behaviour.region, f.objective, f.behaviour.representative);
    if (!search_.write_vectors) f.behaviour.region = WeightRegion{};
  }

  /// The rows of the files for the behaviours of the whole grid (one search's, or the shards'
  /// merged by merged()). Mode best keeps the optimal ones (every tie): the others were found
  /// before a better one was.
  SearchRows rows(Searched searched, const json& shards = nullptr) {
    std::vector<Found>& found = searched.found;
    const std::size_t n = instance_count();
    if (search_.mode == WeightSearch::Mode::Best) {
      const double sign = direction_sign();
      double optimum = std::numeric_limits<double>::infinity();
      for (const Found& f : found) {
        if (!std::isnan(f.objective)) optimum = std::min(optimum, sign * f.objective);
      }
      std::erase_if(found, [&](const Found& f) { return !(sign * f.objective == optimum); });
      searched.stats.best = optimum;
      for (const Found& f : found) optimal_vectors_ += f.behaviour.vectors;
    }
    std::sort(found.begin(), found.end(), [](const Found& a, const Found& b) {
      return a.behaviour.representative < b.behaviour.representative;
    });
    for (Found& f : found) {
      for (const Columns& cells : f.cells) {
        std::vector<double> values;
        for (const auto& [name, cell] : cells) values.push_back(number_of(cell));
        f.values.push_back(std::move(values));
      }
    }
    SearchRows rows;
    write_behaviours(found, instance_specs(), rows);
    write_best_and_ranks(found, rows);
    if (search_.mode == WeightSearch::Mode::All) {
      write_summary(found, n, rows);
      write_heatmaps(found, rows);
    }
    if (search_.write_vectors) write_vectors(found, rows);
    rows.record = record(found, searched, shards);
    return rows;
  }

  /// The parts of the whole grid's behaviours that searches of its shards found in `dirs`,
  /// merged: behaviours with one trace are one behaviour of the whole search (Behaviour::trace),
  /// its region the union of theirs. `records`: each shard's searches.json record of this search.
  Searched merged(const std::vector<std::string>& dirs, const std::vector<json>& records) {
    Searched out;
    const std::string key = unit_key(instance_count());
    std::map<std::uint64_t, std::size_t> by_trace;
    for (const std::string& dir : dirs) {
      for (Found& f : read_journal(key, dir, false, false).found) {
        const auto [at, is_new] = by_trace.emplace(f.behaviour.trace, out.found.size());
        if (is_new) {
          out.found.push_back(std::move(f));
          continue;
        }
        Behaviour& b = out.found[at->second].behaviour;
        b.region = WeightGrid::united(b.region, f.behaviour.region);
        b.vectors = grid_.count(b.region);
        b.representative = grid_.lexmin(b.region);
        b.bounds = grid_.bounds(b.region);
      }
    }
    std::uint64_t vectors = 0;
    for (Found& f : out.found) {
      vectors += f.behaviour.vectors;
      admit(f);
    }
    if (search_.mode == WeightSearch::Mode::All && vectors != grid_.size()) {
      throw ConfigError(journal_path(dirs.front()), "the shards' journals hold the behaviours of " +
                                                        std::to_string(vectors) + " of the search's " +
                                                        std::to_string(grid_.size()) +
                                                        " weight vectors; rerun the shards that lack some");
    }
    for (const json& r : records) {
      out.stats.splits += r.at("splits").get<std::uint64_t>();
      out.stats.forks += r.at("forks").get<std::uint64_t>();
      out.wall_s += r.at("wall_s").get<double>();
      const json& c = r.at("certificate");
      if (c.is_null()) continue;
      out.stats.behaviours += c.at("finished_behaviours").get<std::uint64_t>();
      out.stats.pruned_regions += c.at("pruned_regions").get<std::uint64_t>();
      out.stats.pruned_vectors += c.at("pruned_vectors").get<std::uint64_t>();
      if (!c.at("smallest_pruned_bound").is_null()) {
        out.stats.smallest_pruned_bound = std::min(
            out.stats.smallest_pruned_bound, direction_sign() * c.at("smallest_pruned_bound").get<double>());
      }
    }
    return out;
  }

  /// The record of one shard's search in its searches.json (the files are written by merge).
  [[nodiscard]] json shard_record(const Searched& searched, std::uint64_t index, std::uint64_t count) const {
    json r = record(searched.found, searched, nullptr);
    r["shard"] = {{"index", index}, {"count", count}};
    return r;
  }

  /// The journal of finished behaviours in `dir`, shared by the sweep's searches.
  [[nodiscard]] static std::string journal_path(const std::string& dir) {
    return dir + "/" + kSearchJournalFile;
  }

  /// What a journal line must match to be this search's: its instances (every resolved
  /// parameter), box, objective and mode, and the journal's format (2: with finished subtrees;
  /// a journal of format 1 is not read, and its search is redone).
  [[nodiscard]] std::string unit_key(std::size_t instances) const {
    json key = json::array();
    for (std::size_t i = 0; i < instances; ++i) key.push_back(plan_.search_instance_json(unit_, i));
    key.push_back(search_.values);
    key.push_back(std::string(objective_.name));
    key.push_back(search_.mode == WeightSearch::Mode::All ? "all" : "best");
    key.push_back("journal 3");
    return sweep_hash(key);  // the FNV-1a 64 of its dump, as the manifest's hash of a sweep
  }

  /// The class mean of the objective's cells.
  [[nodiscard]] double objective_of(const std::vector<Columns>& cells) const {
    double sum = 0.0;
    for (const Columns& c : cells) {
      const auto it =
          std::find_if(c.begin(), c.end(), [&](const auto& cell) { return cell.first == objective_.column; });
      sum += it == c.end() ? kNoValue : number_of(it->second);
    }
    return sum / static_cast<double>(cells.size());
  }

  /// One journal line: the key, the behaviour's region and choices, its cells per instance.
  [[nodiscard]] static std::string journal_line(const std::string& key, const Found& f) {
    json boxes = json::array();
    for (const WeightRegion::Box& b : f.behaviour.region.whole) {
      boxes.push_back({b.lo[0], b.lo[1], b.lo[2], b.lo[3], b.hi[0], b.hi[1], b.hi[2], b.hi[3]});
    }
    json parts = json::array();
    for (const WeightRegion::Part& p : f.behaviour.region.parts) {
      parts.push_back({p.block, point_runs(p.bits)});
    }
    json cells = json::array();
    for (const Columns& c : f.cells) {
      json row = json::array();
      for (const auto& [name, cell] : c) row.push_back(cell);
      cells.push_back(std::move(row));
    }
    return json{{"key", key},     {"trace", hex64(f.behaviour.trace)}, {"boxes", boxes},
                {"parts", parts}, {"choices", f.behaviour.choices},    {"cells", cells}}
        .dump();
  }

  /// A part of a journaled region: its block and its points as point_runs(), or (journals
  /// written before 2026-12-04) as the 64 words of its bits in hexadecimal.
  [[nodiscard]] static WeightRegion::Part part_of(const json& p) {
    WeightRegion::Part part;
    part.block = p.at(0).get<std::uint32_t>();
    const json& points = p.at(1);
    if (points.is_array()) {
      part.bits = bits_of_runs(points.get<std::vector<std::uint32_t>>());
    } else {
      const std::string hex = points.get<std::string>();
      if (hex.size() != part.bits.size() * 16) throw std::runtime_error("bad part");
      for (std::size_t w = 0; w < part.bits.size(); ++w) {
        part.bits[w] = std::stoull(hex.substr(w * 16, 16), nullptr, 16);
      }
    }
    return part;
  }

  /// The journal line of a finished subtree: its id and tally (the bound signed as the search
  /// minimises it).
  [[nodiscard]] static std::string done_line(const std::string& key, std::uint64_t id,
                                             const SubtreeTally& t) {
    return json{{"key", key},
                {"done", hex64(id)},
                {"vectors", t.vectors},
                {"behaviours", t.behaviours},
                {"pruned_regions", t.pruned_regions},
                {"pruned_vectors", t.pruned_vectors},
                {"smallest_pruned_bound",
                 std::isfinite(t.smallest_pruned_bound) ? json(t.smallest_pruned_bound) : json(nullptr)}}
        .dump();
  }

  /// This search's behaviours and finished subtrees in the journal of `dir`. A line that does not parse (the
  /// torn last line of a killed search) ends the reading. `repair` (a search about to append): the file is
  /// cut to the lines before it, so that new lines follow complete ones. Otherwise (a merge reads
  /// a finished shard, whose journal must be whole) it is a ConfigError naming the line, and the
  /// file is left as it is.
  /// `admitting`: each behaviour goes through admit() as it is read (a resumed search's own
  /// journal; a merge admits the behaviours the shards' parts make up).
  [[nodiscard]] Journal read_journal(const std::string& key, const std::string& dir, bool repair,
                                     bool admitting) {
    Journal out;
    const std::string path = journal_path(dir);
    std::ifstream in(path, std::ios::binary);
    if (!in) return out;
    const Columns names =
        instance_cells(RunResult{}, plan_.maps().at(unit_.maps.front()), plan_.search_instance(unit_, 0));
    std::string line;
    std::uintmax_t kept_bytes = 0;  // the lines before a damaged one (a journal may hold gigabytes)
    std::size_t number = 0;
    bool torn = false;
    while (std::getline(in, line)) {
      ++number;
      json j;
      try {
        if (in.eof()) throw std::runtime_error("no newline");
        j = parse_json_bounded(line, path);
        if (j.at("key").get<std::string>() == key && j.contains("done")) {
          const std::string id = j.at("done").get<std::string>();
          if (id.size() != 16) throw std::runtime_error("bad subtree id");
          SubtreeTally t;
          t.vectors = j.at("vectors").get<std::uint64_t>();
          t.behaviours = j.at("behaviours").get<std::uint64_t>();
          t.pruned_regions = j.at("pruned_regions").get<std::uint64_t>();
          t.pruned_vectors = j.at("pruned_vectors").get<std::uint64_t>();
          const json& bound = j.at("smallest_pruned_bound");
          if (!bound.is_null()) t.smallest_pruned_bound = bound.get<double>();
          out.done.emplace(std::stoull(id, nullptr, 16), t);
        } else if (j.at("key").get<std::string>() == key) {
          Found f;
          for (const json& b : j.at("boxes")) {
            WeightRegion::Box box;
            for (std::size_t k = 0; k < 4; ++k) {
              box.lo[k] = b.at(k).get<std::uint32_t>();
              box.hi[k] = b.at(k + 4).get<std::uint32_t>();
            }
            f.behaviour.region.whole.push_back(box);
          }
          for (const json& p : j.at("parts")) f.behaviour.region.parts.push_back(part_of(p));
          f.behaviour.choices = j.at("choices").get<std::vector<int>>();
          const std::string trace = j.at("trace").get<std::string>();
          if (trace.size() != 16) throw std::runtime_error("bad trace");
          f.behaviour.trace = std::stoull(trace, nullptr, 16);
          for (const json& row : j.at("cells")) {
            if (row.size() != names.size()) throw std::runtime_error("another build's columns");
            Columns c = names;
            for (std::size_t m = 0; m < c.size(); ++m) c[m].second = row.at(m).get<std::string>();
            f.cells.push_back(std::move(c));
          }
          if (!grid_.holds(f.behaviour.region)) throw std::runtime_error("a region outside the search's box");
          if (f.behaviour.region.empty() ||
              f.cells.size() != static_cast<std::size_t>(unit_.maps.size()) *
                                    static_cast<std::size_t>(plan_.repetitions())) {
            throw std::runtime_error("not a behaviour of this search");
          }
          f.behaviour.vectors = grid_.count(f.behaviour.region);
          f.behaviour.representative = grid_.lexmin(f.behaviour.region);
          f.behaviour.bounds = grid_.bounds(f.behaviour.region);
          f.objective = objective_of(f.cells);
          if (admitting) admit(f);
          out.found.push_back(std::move(f));
        }
      } catch (const std::exception& e) {
        if (!repair) {
          throw ConfigError(path + ":" + std::to_string(number),
                            std::string(e.what()) +
                                "; the shard's journal is damaged: delete its searches.json and rerun its "
                                "`fsweep run --shard i/N`, which keeps the lines before this one and redoes "
                                "the rest");
        }
        std::fprintf(stderr,
                     "fsweep: %s:%zu: %s; this line and the rest are dropped (the search redoes them)\n",
                     path.c_str(), number, e.what());
        torn = true;
        break;
      }
      kept_bytes += line.size() + 1;
    }
    in.close();
    if (torn) std::filesystem::resize_file(path, kept_bytes);
    return out;
  }

  /// Header lines (no newline) of the files (report/search_schema.hpp).
  static std::string behaviours_header(const WeightSearch& s) {
    return csv_record(behaviours_columns(s.weights));
  }

 private:
  [[nodiscard]] std::string value_at(int k, int index) const {
    return format_number(grid_.values(k)[static_cast<std::size_t>(index)]);
  }

  void write_behaviours(const std::vector<Found>& found, const std::vector<RunSpec>& specs,
                        SearchRows& rows) const {
    const int w = grid_.weights();
    for (std::size_t b = 0; b < found.size(); ++b) {
      const Behaviour& be = found[b].behaviour;
      std::vector<std::string> head{id_, std::to_string(b), std::to_string(be.vectors)};
      for (int k = 0; k < w; ++k) head.push_back(value_at(k, be.representative[static_cast<std::size_t>(k)]));
      for (int k = 0; k < w; ++k) {
        head.push_back(value_at(k, be.bounds[static_cast<std::size_t>(k)][0]));
        head.push_back(value_at(k, be.bounds[static_cast<std::size_t>(k)][1]));
      }
      head.push_back(number_cell(found[b].objective));
      for (std::size_t i = 0; i < found[b].cells.size(); ++i) {
        std::vector<std::string> row = head;
        const std::size_t map = unit_.maps[i / static_cast<std::size_t>(plan_.repetitions())];
        row.push_back(std::to_string(i));
        row.push_back(plan_.maps().at(map).label);
        row.push_back(std::to_string(specs[i].seed));
        for (const auto& [name, cell] : found[b].cells[i]) row.push_back(cell);
        rows.behaviours += csv_record(row) + '\n';
      }
    }
  }

  void write_summary(const std::vector<Found>& found, std::size_t instances, SearchRows& rows) {
    const StrategyEntry& entry = plan_.strategies().at(unit_.entry);
    std::vector<std::string> row{id_,
                                 entry.label,
                                 unit_.map_class,
                                 planner_label(plan_.planners().at(unit_.planner)),
                                 plan_.robots().at(unit_.robot).label,
                                 std::to_string(instances),
                                 std::to_string(grid_.size()),
                                 std::to_string(found.size())};
    // End reasons, weighted.
    for (int r = static_cast<int>(EndReason::Complete); r <= static_cast<int>(EndReason::Error); ++r) {
      const std::string reason(to_string(static_cast<EndReason>(r)));
      std::uint64_t count = 0;
      for (const Found& f : found) {
        for (const Columns& c : f.cells) count += c.front().second == reason ? f.behaviour.vectors : 0;
      }
      row.push_back(std::to_string(count));
    }
    // Metrics: counted values over vectors x instances.
    const Columns& names = found.front().cells.front();
    for (std::size_t m = 0; m < names.size(); ++m) {
      if (names[m].first == kEndReasonColumn || names[m].first == kEndDetailColumn ||
          is_effort_column(names[m].first)) {
        continue;
      }
      std::vector<CountedValue> values;
      for (const Found& f : found) {
        for (const auto& v : f.values) {
          if (!std::isnan(v[m])) values.push_back({v[m], f.behaviour.vectors});
        }
      }
      if (values.empty()) {
        row.insert(row.end(), kStatisticNames.size(), std::string());
        continue;
      }
      for (const double s : describe_counted(values)) row.push_back(format_number(s));
    }
    rows.summary = csv_record(row) + '\n';
  }

 public:
  static std::string summary_header() { return csv_record(search_summary_columns()); }
  static std::string best_header(const WeightSearch& s) { return csv_record(search_best_columns(s.weights)); }
  static std::string ranks_header(const WeightSearch& s) {
    return csv_record(search_ranks_columns(s.weights));
  }
  static std::string heatmaps_header() { return csv_record(search_heatmaps_columns()); }
  static std::string vectors_header(const WeightSearch& s) { return csv_record(vectors_columns(s.weights)); }

 private:
  /// Vectors strictly better than `objective` and those equal to it.
  [[nodiscard]] std::pair<std::uint64_t, std::uint64_t> standing(const std::vector<Found>& found,
                                                                 double objective) const {
    std::uint64_t better_count = 0;
    std::uint64_t tied = 0;
    for (const Found& f : found) {
      if (better(f.objective, objective, objective_.direction)) better_count += f.behaviour.vectors;
      const bool equal = f.objective == objective || (std::isnan(f.objective) && std::isnan(objective));
      if (equal) tied += f.behaviour.vectors;
    }
    return {better_count, tied};
  }

  void write_best_and_ranks(const std::vector<Found>& found, SearchRows& rows) const {
    std::vector<std::size_t> order(found.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return better(found[a].objective, found[b].objective, objective_.direction);
    });
    std::uint64_t before = 0;        // vectors of the behaviours listed so far
    std::uint64_t better_count = 0;  // vectors strictly better than this behaviour
    for (std::size_t r = 0; r < order.size(); ++r) {
      const Found& f = found[order[r]];
      if (r == 0 || better(found[order[r - 1]].objective, f.objective, objective_.direction))
        better_count = before;
      if (search_.mode == WeightSearch::Mode::Best && better_count > 0) break;
      std::vector<std::string> row{id_,
                                   std::to_string(better_count + 1),
                                   std::to_string(order[r]),
                                   std::to_string(f.behaviour.vectors),
                                   std::to_string(better_count),
                                   number_cell(f.objective)};
      for (int k = 0; k < grid_.weights(); ++k) {
        row.push_back(value_at(k, f.behaviour.representative[static_cast<std::size_t>(k)]));
      }
      rows.best += csv_record(row) + '\n';
      before += f.behaviour.vectors;
    }
    for (std::size_t r = 0; r < search_.rank.size(); ++r) {
      const std::vector<double>& vector = search_.rank[r];
      const auto owner = std::find_if(found.begin(), found.end(), [&](const Found& f) {
        return std::find(f.ranked.begin(), f.ranked.end(), r) != f.ranked.end();
      });
      if (owner == found.end()) throw std::logic_error("exact search: a vector of the box in no behaviour");
      const auto [better_count, tied] = standing(found, owner->objective);
      std::vector<std::string> row{id_};
      for (const double v : vector) row.push_back(format_number(v));
      row.push_back(std::to_string(owner - found.begin()));
      row.push_back(number_cell(owner->objective));
      row.push_back(std::to_string(better_count + 1));
      row.push_back(std::to_string(better_count));
      row.push_back(std::to_string(tied));
      row.push_back(
          format_number(100.0 * static_cast<double>(better_count) / static_cast<double>(grid_.size())));
      rows.ranks += csv_record(row) + '\n';
    }
  }

  void write_heatmaps(const std::vector<Found>& found, SearchRows& rows) const {
    // found is in id order, which is the order of the representatives.
    const auto id_of = [&](const Point& representative) {
      const auto it =
          std::lower_bound(found.begin(), found.end(), representative,
                           [](const Found& f, const Point& p) { return f.behaviour.representative < p; });
      return static_cast<std::int64_t>(it - found.begin());
    };
    for (const HeatMaps::Map& m : heat_.maps()) {
      const std::size_t nb = grid_.values(m.b).size();
      for (std::size_t cell = 0; cell < m.best.size(); ++cell) {
        rows.heatmaps += csv_record({id_, search_.weights[static_cast<std::size_t>(m.a)],
                                     search_.weights[static_cast<std::size_t>(m.b)],
                                     value_at(m.a, static_cast<int>(cell / nb)),
                                     value_at(m.b, static_cast<int>(cell % nb)), number_cell(m.best[cell]),
                                     std::to_string(m.set[cell] != 0 ? id_of(m.owner[cell]) : -1)}) +
                         '\n';
      }
    }
  }

  void write_vectors(const std::vector<Found>& found, SearchRows& rows) const {
    // The owner of every vector, by its lexicographic position in the box.
    const int w = grid_.weights();
    std::vector<std::uint32_t> owner(grid_.size());
    for (std::size_t f = 0; f < found.size(); ++f) {
      grid_.for_each_point(found[f].behaviour.region, [&](const Point& at) {
        std::uint64_t index = 0;
        for (int k = 0; k < w; ++k)
          index =
              index * grid_.values(k).size() + static_cast<std::uint64_t>(at[static_cast<std::size_t>(k)]);
        owner[index] = static_cast<std::uint32_t>(f);
      });
    }
    Point at{};
    for (std::uint64_t index = 0; index < owner.size(); ++index) {
      std::uint64_t rest = index;
      for (int k = w - 1; k >= 0; --k) {
        const std::uint64_t size = grid_.values(k).size();
        at[static_cast<std::size_t>(k)] = static_cast<int>(rest % size);
        rest /= size;
      }
      rows.vectors += id_;
      for (int k = 0; k < w; ++k) rows.vectors += ',' + value_at(k, at[static_cast<std::size_t>(k)]);
      rows.vectors += ',' + std::to_string(owner[index]) + '\n';
    }
  }

  /// Mode best: what was pruned (null in mode all).
  [[nodiscard]] json certificate(const ExactSearchStats& stats) const {
    if (search_.mode == WeightSearch::Mode::All) return nullptr;
    const double sign = direction_sign();
    return json{{"optimum", std::isfinite(stats.best) ? json(sign * stats.best) : json(nullptr)},
                {"optimal_vectors", optimal_vectors_},
                {"finished_behaviours", stats.behaviours},
                {"pruned_regions", stats.pruned_regions},
                {"pruned_vectors", stats.pruned_vectors},
                {"smallest_pruned_bound", std::isfinite(stats.smallest_pruned_bound)
                                              ? json(sign * stats.smallest_pruned_bound)
                                              : json(nullptr)},
                {"note",
                 "every pruned vector's objective is at least smallest_pruned_bound, worse than the "
                 "optimum; the counts depend on the order threads finished behaviours in"}};
  }

  /// The search's searches.json record. `shards`: the records of the shards it was merged from.
  [[nodiscard]] json record(const std::vector<Found>& found, const Searched& searched,
                            const json& shards) const {
    const ExactSearchStats& stats = searched.stats;
    json box = json::object();
    for (std::size_t k = 0; k < search_.weights.size(); ++k) box[search_.weights[k]] = search_.values[k];
    json specs = json::array();
    for (std::size_t i = 0; i < instance_count(); ++i) specs.push_back(plan_.search_instance_json(unit_, i));
    std::vector<std::string> maps;
    for (const std::size_t m : unit_.maps) maps.push_back(plan_.maps().at(m).label);
    return json{{kSearchIdColumn, std::stoi(id_)},
                {"strategy_label", plan_.strategies().at(unit_.entry).label},
                {"map_class", unit_.map_class},
                {"maps", maps},
                {"repetitions", plan_.repetitions()},
                {"planner", planner_label(plan_.planners().at(unit_.planner))},
                {"robot", plan_.robots().at(unit_.robot).label},
                {"mode", search_.mode == WeightSearch::Mode::All ? "all" : "best"},
                {"objective", std::string(objective_.name)},
                {"box", box},
                {"vectors", grid_.size()},
                {"behaviours", found.size()},
                {"distinct_outcomes", distinct_outcomes(found)},
                {"resumed_behaviours", searched.resumed},
                {"splits", stats.splits},
                {"forks", stats.forks},
                {"certificate", certificate(stats)},
                {"wall_s", searched.wall_s},
                {"merged_from_shards", shards},
                {"instances", specs}};
  }

  /// Branch and bound minimises direction_sign() x the objective: 1 for a minimised objective, -1 for a
  /// maximised one.
  [[nodiscard]] double direction_sign() const {
    return objective_.direction == Direction::Minimize ? 1.0 : -1.0;
  }

  /// The class's instances: its maps times the repetitions (SweepPlan::search_instance()).
  [[nodiscard]] std::size_t instance_count() const {
    return unit_.maps.size() * static_cast<std::size_t>(plan_.repetitions());
  }
  [[nodiscard]] std::vector<RunSpec> instance_specs() const {
    std::vector<RunSpec> specs;
    for (std::size_t i = 0; i < instance_count(); ++i) specs.push_back(plan_.search_instance(unit_, i));
    return specs;
  }
  [[nodiscard]] const SweepMap& instance_map(std::size_t instance) const {
    return plan_.maps().at(unit_.maps[instance / static_cast<std::size_t>(plan_.repetitions())]);
  }

  std::string out_dir_;
  const SweepPlan& plan_;
  const SearchUnit& unit_;
  std::string id_;
  const WeightSearch& search_;
  WeightGrid grid_;
  const Objective& objective_;
  /// Mode all: the heat maps and the positions in the grid of the `rank` vectors.
  HeatMaps heat_;
  std::vector<Point> rank_points_;
  std::uint64_t optimal_vectors_ = 0;
};

/// The searches of `plan` (checked: one set of weight names) and the objective.
std::vector<SearchUnit> checked_units(const SweepPlan& plan, const Objective*& objective) {
  std::vector<SearchUnit> units = plan.search_units();
  objective = find_objective(plan.objective());
  if (objective == nullptr)
    throw ConfigError("output/objective", "unknown objective '" + plan.objective() + "'");
  // Each file has the header of the first search's entry: every search entry's weights head its
  // columns.
  for (const SearchUnit& u : units) {
    const WeightSearch& first = *plan.strategies().at(units.front().entry).search;
    const WeightSearch& s = *plan.strategies().at(u.entry).search;
    if (s.weights != first.weights) {
      throw ConfigError("/strategies/" + std::to_string(u.entry) + "/search",
                        "every search entry of one sweep must search the same weights (" +
                            join_names(first.weights) + "); got " + join_names(s.weights));
    }
  }
  return units;
}

/// Writes the files of the searches `units` of `plan` from their rows (one per unit) into
/// `out_dir`, searches.json last, and counts them in `report`.
void write_search_files(const SweepPlan& plan, const std::vector<SearchUnit>& units,
                        std::vector<SearchRows> rows, const std::string& out_dir, SearchRunReport& report) {
  const WeightSearch& first = *plan.strategies().at(units.front().entry).search;
  std::string behaviours = SearchWriter::behaviours_header(first) + '\n';
  std::string summary = SearchWriter::summary_header() + '\n';
  std::string best = SearchWriter::best_header(first) + '\n';
  std::string ranks = SearchWriter::ranks_header(first) + '\n';
  std::string heatmaps = SearchWriter::heatmaps_header() + '\n';
  std::string vectors = SearchWriter::vectors_header(first) + '\n';
  bool any_vectors = false;
  bool any_all = false;
  json searches = json::array();
  for (std::size_t id = 0; id < units.size(); ++id) {
    const WeightSearch& s = *plan.strategies().at(units[id].entry).search;
    behaviours += rows[id].behaviours;
    summary += rows[id].summary;
    best += rows[id].best;
    ranks += rows[id].ranks;
    heatmaps += rows[id].heatmaps;
    vectors += rows[id].vectors;
    any_vectors = any_vectors || s.write_vectors;
    any_all = any_all || s.mode == WeightSearch::Mode::All;
    (s.mode == WeightSearch::Mode::All ? report.behaviours : report.optimal) +=
        rows[id].record.at("behaviours").get<std::uint64_t>();
    report.vectors += s.vectors();
    searches.push_back(std::move(rows[id].record));
  }
  const std::filesystem::path dir(out_dir);
  std::vector<std::pair<std::string, const std::string*>> files{{kBehavioursFile, &behaviours},
                                                                {kSearchBestFile, &best}};
  if (any_all) {
    files.emplace_back(kSearchSummaryFile, &summary);
    files.emplace_back(kSearchRanksFile, &ranks);
    files.emplace_back(kSearchHeatmapsFile, &heatmaps);
  }
  if (any_vectors) files.emplace_back(kVectorsFile, &vectors);
  for (const auto& [name, text] : files) {
    write_file_atomically((dir / name).string(), *text);
    report.files.push_back(name);
  }
  // Last: its presence marks the search files as complete.
  write_file_atomically((dir / kSearchesFile).string(), json{{"searches", searches}}.dump(2) + '\n');
  report.files.emplace_back(kSearchesFile);
  report.searches = units.size();
}

}  // namespace

SearchRunReport run_weight_searches(const SweepPlan& plan, const std::string& out_dir, int threads,
                                    bool progress, std::uint64_t shard_index, std::uint64_t shard_count,
                                    const std::atomic<bool>* stop) {
  SearchRunReport report;
  const Objective* objective = nullptr;
  const std::vector<SearchUnit> units = checked_units(plan, objective);
  if (units.empty()) return report;
  if (threads < 1) throw std::invalid_argument("run_weight_searches: threads must be >= 1");
  if (shard_count == 0 || shard_index >= shard_count) {
    throw std::invalid_argument("run_weight_searches: shard " + std::to_string(shard_index) + " of " +
                                std::to_string(shard_count));
  }
  const auto start = std::chrono::steady_clock::now();
  std::vector<WeightRegion> roots;
  std::uint64_t total = 0;
  for (const SearchUnit& u : units) {
    const WeightGrid grid(plan.strategies().at(u.entry).search->values);
    roots.push_back(shard_count > 1 ? grid.shard(shard_index, shard_count) : grid.everything());
    total += grid.count(roots.back());
  }
  ProgressMeter meter(total, "weight vectors", progress);
  std::uint64_t done = 0;
  std::mutex mutex;
  std::vector<SearchRows> rows;
  json shard_records = json::array();
  for (std::size_t id = 0; id < units.size(); ++id) {
    SearchWriter writer(plan, units[id], id, *objective, out_dir);
    Searched searched = writer.search(
        threads,
        [&](std::uint64_t n) {
          const std::lock_guard<std::mutex> lock(mutex);
          done += n;
          meter.update(done, 0);
        },
        roots[id], stop);
    if (searched.stats.stopped) {
      meter.finish(done, 0);
      if (progress) {
        std::fputs("fsweep: weight search stopped; what it finished is in search_journal.jsonl\n", stderr);
      }
      report.interrupted = true;
      report.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return report;
    }
    if (shard_count > 1) {
      shard_records.push_back(writer.shard_record(searched, shard_index, shard_count));
    } else {
      rows.push_back(writer.rows(std::move(searched)));
    }
  }
  meter.finish(done, 0);
  if (shard_count > 1) {
    // A shard's searches are parts: merge_weight_searches() writes the files. Its searches.json
    // marks it complete.
    write_file_atomically(out_dir + "/" + kSearchesFile, json{{"searches", shard_records}}.dump(2) + '\n');
    report.files.emplace_back(kSearchesFile);
    report.searches = units.size();
  } else {
    write_search_files(plan, units, std::move(rows), out_dir, report);
  }
  report.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

SearchRunReport merge_weight_searches(const SweepPlan& plan, const std::string& out_dir,
                                      const std::vector<std::string>& shard_dirs) {
  SearchRunReport report;
  const Objective* objective = nullptr;
  const std::vector<SearchUnit> units = checked_units(plan, objective);
  if (units.empty()) return report;
  const auto start = std::chrono::steady_clock::now();
  // Each shard's record of each search: its searches.json says the shard's searches finished.
  std::vector<std::vector<json>> records(units.size());
  for (const std::string& dir : shard_dirs) {
    const std::string path = dir + "/" + kSearchesFile;
    const std::optional<std::string> text = read_file(path);
    if (!text) {
      throw ConfigError(path,
                        "missing: the shard's weight searches did not finish; rerun `fsweep run --shard` "
                        "for it (it resumes from its search_journal.jsonl)");
    }
    json shard;
    try {
      shard = parse_json_bounded(*text, path);
      const json& list = shard.at("searches");
      if (list.size() != units.size()) {
        throw std::runtime_error("has " + std::to_string(list.size()) + " searches, the sweep " +
                                 std::to_string(units.size()));
      }
      for (std::size_t id = 0; id < units.size(); ++id) records[id].push_back(list.at(id));
    } catch (const std::exception& e) {
      throw ConfigError(path, std::string("not a shard's searches.json of this sweep: ") + e.what());
    }
  }
  std::vector<SearchRows> rows;
  for (std::size_t id = 0; id < units.size(); ++id) {
    SearchWriter writer(plan, units[id], id, *objective, out_dir);
    rows.push_back(writer.rows(writer.merged(shard_dirs, records[id]), json(records[id])));
  }
  write_search_files(plan, units, std::move(rows), out_dir, report);
  report.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace sweep
}  // namespace fsweep
