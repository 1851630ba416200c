#include "sweep/weight_search_runner.hpp"

#include <oneapi/tbb/info.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
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
#include "core/memory_watch.hpp"
#include "core/readable_number.hpp"
#include "core/statistics.hpp"
#include "report/runs_schema.hpp"
#include "report/search_objective.hpp"
#include "report/search_schema.hpp"
#include "sim/heuristics.hpp"
#include "sweep/manifest.hpp"
#include "sweep/progress_meter.hpp"
#include "sweep/search_anytime.hpp"
#include "sweep/search_certificate.hpp"
#include "sweep/search_tables.hpp"
#include "sweep/sweep_axes.hpp"
#include "sweep/sweep_table.hpp"
#include "weightsearch/exact_search.hpp"
#include "weightsearch/search_journal.hpp"
#include "weightsearch/search_probes.hpp"
#include "weightsearch/weight_grid.hpp"

namespace fsweep {
inline namespace sweep {
namespace {

using nlohmann::json;
/// What a search's journal holds: its behaviours, and the subtrees of its region tree whose
/// every leaf had finished or been pruned (by id, SubtreeJournal).
struct Journal {
  std::vector<FoundBehaviour> found;
  std::unordered_map<std::uint64_t, SubtreeTally> done;
  /// Branch and bound's other leaves (pruned and beaten): their paths and tallies.
  std::vector<std::pair<std::vector<int>, SubtreeTally>> leaves;
  /// True when no line of the search was read.
  [[nodiscard]] bool empty() const { return found.empty() && done.empty() && leaves.empty(); }
  /// Lines of the same search in SearchJournal::kPreviousFormat, for a class of several
  /// instances (their subtree ids name regions of another tree): counted, not read.
  std::size_t previous_lines = 0;
};

/// The cells' text, per instance (a journal line holds no column names).
std::vector<std::vector<std::string>> cell_texts(const std::vector<Columns>& cells) {
  std::vector<std::vector<std::string>> out;
  for (const Columns& row : cells) {
    std::vector<std::string>& texts = out.emplace_back();
    for (const auto& [name, cell] : row) texts.push_back(cell);
  }
  return out;
}

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

/// What one search (or one shard's, or the shards' merged) found.
struct Searched {
  std::vector<FoundBehaviour> found;
  /// Of them, read from the journal of a killed search.
  std::size_t resumed = 0;
  ExactSearchStats stats;
  /// False for a merge of shards some of whose records have no `steps` (older builds'):
  /// searches.json's `steps` is then null.
  bool steps_known = true;
  double wall_s = 0.0;
  /// Mode best: where the search stands (describe_search_status() of its last anytime status);
  /// empty in mode all.
  std::string standing;
  /// Set when the memory guard stopped it (stats.stopped is set too).
  std::optional<MemoryStop> memory_stop;
};

/// The memory guard reads the memory in use every this many behaviours found or read back from
/// the journal (besides every kMemoryWatchInterval): a check costs a few microseconds, a
/// behaviour milliseconds to find and a tenth of one to read back.
constexpr std::size_t kBehavioursPerMemoryCheck = 16;

/// What formatting a finished search's files takes beyond what the search held, per row of
/// behaviours.csv (a behaviour times an instance), with room: the free-space box [0, 15]^4 (6,834
/// behaviours, one instance) went from 71.7 to 84.0 MiB resident (1.8 KB a row) while formatting.
constexpr std::uint64_t kFormattingBytesPerRow = 2048;

/// What the guard `memory` reads as the memory in use: its own reader, else the resident set.
MemoryWatch::Reader memory_reader(const SearchMemoryGuard& memory) {
  return memory.resident ? memory.resident : MemoryWatch::Reader(resident_memory_bytes);
}

/// A stop at `stage` (Writing or Merging) when formatting `rows` rows of behaviours.csv for a
/// finished search that holds `held` behaviours (kFormattingBytesPerRow a row) would take the
/// memory in use past `guard`'s threshold; nullopt without a guard or when it fits.
std::optional<MemoryStop> formatting_would_pass(const MemoryWatch* guard, const SearchMemoryGuard& memory,
                                                std::size_t held, std::size_t rows, MemoryStop::Stage stage) {
  if (guard == nullptr) return std::nullopt;
  const std::uint64_t in_use = memory_reader(memory)().value_or(0);
  const std::uint64_t needed = rows * kFormattingBytesPerRow;
  if (in_use + needed < guard->threshold_bytes()) return std::nullopt;
  MemoryStop s;
  s.in_use_bytes = in_use;
  s.needed_bytes = needed;
  s.held_behaviours = held;
  s.stage = stage;
  return s;
}

/// True when `guard` (may be null) has seen the memory reach its threshold, reading it at every
/// kBehavioursPerMemoryCheck-th behaviour (`held`: the behaviours held so far).
bool past_memory_threshold(MemoryWatch* guard, std::size_t held) {
  if (guard == nullptr) return false;
  return guard->reached() || (held % kBehavioursPerMemoryCheck == 0 && guard->check());
}

/// `out` as the memory guard `guard` stopped it at `stage`: stats.stopped, and the memory stop
/// with the behaviours and branches it held (its search id, limit and message are the caller's).
Searched stopped_by_memory(Searched out, const MemoryWatch& guard, MemoryStop::Stage stage) {
  out.stats.stopped = true;
  MemoryStop& s = out.memory_stop.emplace();
  s.in_use_bytes = guard.reached().value_or(0);
  s.held_behaviours = out.found.size();
  s.open_branches = out.stats.unresolved_branches;
  s.stage = stage;
  return out;
}

/// What a memory stop says (MemoryStop::message): what happened, what the journal keeps, and
/// the ways on for a search of `search`.
std::string describe_memory_stop(const MemoryStop& s, const WeightSearch& search) {
  const auto in_use = [&s] {
    std::string text = readable_memory_size(s.in_use_bytes);
    if (s.needed_bytes > 0) text += " and would need about " + readable_memory_size(s.needed_bytes) + " more";
    return text + ", past " + readable_number(kMemorySafetyShare * 100.0) + "% of the limit of " +
           readable_memory_size(s.limit.bytes) + " (" + s.limit.source + "), holding " +
           readable_number(static_cast<double>(s.held_behaviours)) + " behaviours";
  };
  if (s.stage == MemoryStop::Stage::Merging) {
    return "merging exact weight search " + std::to_string(s.search_id) + "'s shards " +
           (s.needed_bytes > 0 ? "would pass" : "reached") + " the memory limit: the process used " +
           in_use() +
           "; nothing was written. To go on: rerun fsweep merge with a larger --max-memory where the machine "
           "has the memory (the merge holds every behaviour of the whole search)";
  }
  std::string text = "exact weight search " + std::to_string(s.search_id);
  switch (s.stage) {
    case MemoryStop::Stage::Starting:
      text += " cannot start within the memory limit: before it began, the process used ";
      break;
    case MemoryStop::Stage::Resuming:
      text += " cannot resume within the memory limit: reading its journal back, the process used ";
      break;
    case MemoryStop::Stage::Searching:
      text += " stopped at the memory limit: the process used ";
      break;
    case MemoryStop::Stage::Merging:  // above
    case MemoryStop::Stage::Writing:
      text += s.needed_bytes > 0
                  ? " finished, but formatting its files would pass the memory limit: the process used "
                  : " finished, but formatting its files reached the memory limit: the process used ";
      break;
  }
  if (s.stage == MemoryStop::Stage::Starting) {
    text += readable_memory_size(s.in_use_bytes) + ", past " + readable_number(kMemorySafetyShare * 100.0) +
            "% of the limit of " + readable_memory_size(s.limit.bytes) + " (" + s.limit.source + ")";
  } else {
    text += in_use();
  }
  if (s.open_branches > 0)
    text += " and " + readable_number(static_cast<double>(s.open_branches)) + " open branches";
  text +=
      s.stage == MemoryStop::Stage::Writing
          ? "; search_journal.jsonl holds the whole search and no other search file was written. To go "
            "on: rerun with a larger --max-memory (it reads the journal back and writes the files) where "
            "the machine has the memory, "
          : "; search_journal.jsonl keeps what it finished. To go on: rerun with a larger --max-memory (it "
            "resumes from the journal) where the machine has the memory, ";
  if (search.mode == WeightSearch::Mode::All) {
    text += "search in \"mode\": \"best\" if only the optimal behaviours are needed, ";
  } else if (search.order == SearchOrder::Bound) {
    text += "search in \"order\": \"depth\" or with a smaller \"max_open\" (fewer branches wait), ";
  }
  text += "or search the box in shards (fsweep run --shard i/N; docs/weight-search.md, \"Shards\")";
  return text;
}

/// What a resumed search of `root` takes from its journal (journaled_subtrees()): the
/// ancestors of its finished subtrees (SubtreeJournal::ancestors), and the topmost of them
/// (journal_topmost()), which it skips each once as it comes to them, so what they resolved
/// counts from the start.
struct JournaledTree {
  std::unordered_set<std::uint64_t> ancestors;
  JournalTop top;
};

/// The finished subtrees of a search of `root` that `journaled` holds, added to journaled.done:
/// its nodes, and its behaviours (`found`, read from it) and other leaves as finished leaves.
JournaledTree journaled_subtrees(const WeightRegion& root, const std::vector<FoundBehaviour>& found,
                                 Journal& journaled) {
  const std::uint64_t root_id = subtree_root(root);
  std::vector<std::vector<int>> paths;
  paths.reserve(found.size() + journaled.leaves.size());
  for (const FoundBehaviour& f : found) {
    SubtreeTally leaf;
    leaf.vectors = f.behaviour.vectors;
    leaf.behaviours = 1;
    journaled.done.emplace(subtree_of(root_id, f.behaviour.choices), leaf);
    paths.push_back(f.behaviour.choices);
  }
  for (const auto& [choices, leaf] : journaled.leaves) {
    journaled.done.emplace(subtree_of(root_id, choices), leaf);
    paths.push_back(choices);
  }
  return JournaledTree{journal_ancestors(root_id, paths), journal_topmost(root_id, paths, journaled.done)};
}

class SearchWriter {
 public:
  SearchWriter(const SweepPlan& plan, const SearchUnit& unit, std::size_t id, const Objective& objective,
               std::string out_dir)
      : out_dir_(std::move(out_dir)),
        plan_(plan),
        unit_(unit),
        id_(id),
        search_(*plan.strategies().at(unit.entry).search),
        objective_(objective),
        tables_(plan, unit, id, objective),
        grid_(tables_.grid()) {}
  SearchWriter(const SearchWriter&) = delete;
  SearchWriter& operator=(const SearchWriter&) = delete;

  /// Searches `root` (everything, or a shard: WeightGrid::shard()) and formats what it finds.
  /// `on_vectors(n)`: n more vectors resolved. Every behaviour found and every finished subtree
  /// goes to the journal at once; those a killed search of the same key journaled are kept and
  /// skipped (mode best: the best journaled behaviour is the incumbent to beat).
  ///
  /// `stop`: ends the search early (exact_search). `guard`: the memory guard (may be null), whose
  /// stop() is `stop`, watching while the journal is read back and while the search runs; a
  /// search past its threshold returns stopped_by_memory(): before reading anything when it is
  /// past it at the start, before searching anything when the journal alone reaches it.
  Searched search(int threads, const std::function<void(std::uint64_t)>& on_vectors, const WeightRegion& root,
                  const std::atomic<bool>* stop, MemoryWatch* guard) {
    const std::vector<RunSpec> specs = instance_specs();
    const auto start = std::chrono::steady_clock::now();
    Searched out;
    std::vector<FoundBehaviour>& found = out.found;
    const std::string key = journal_key();
    if (guard != nullptr && guard->check())
      return stopped_by_memory(std::move(out), *guard, MemoryStop::Stage::Starting);
    Journal journaled = read_journal(key, out_dir_, JournalDamage::Repair, true, guard);
    if (journaled.empty() && journaled.previous_lines > 0) note_previous_format(journaled.previous_lines);
    found = std::move(journaled.found);
    if (guard != nullptr && guard->reached())
      return stopped_by_memory(std::move(out), *guard, MemoryStop::Stage::Resuming);
    const JournaledTree tree = journaled_subtrees(root, found, journaled);
    std::unordered_map<std::uint64_t, SubtreeTally>& done = journaled.done;
    const double sign = direction_sign();
    double incumbent = std::numeric_limits<double>::infinity();
    std::vector<double> best_weights;  // of the incumbent, for the anytime status
    const auto better = [&](const FoundBehaviour& f) {
      if (std::isnan(f.objective) || !(sign * f.objective < incumbent)) return;
      incumbent = sign * f.objective;
      best_weights = grid_.weights_at(f.behaviour.representative);
    };
    for (const FoundBehaviour& f : found) better(f);
    out.resumed = found.size();
    SearchJournal journal(journal_path(out_dir_));
    SubtreeJournal subtrees;
    subtrees.done = &done;
    subtrees.ancestors = &tree.ancestors;
    subtrees.on_done = [&](std::uint64_t id, const SubtreeTally& t) { journal.append_done(key, id, t); };
    std::atomic<std::uint64_t> resolved{0};
    const auto count = [&](std::uint64_t n) {
      resolved.fetch_add(n, std::memory_order_relaxed);
      on_vectors(n);
    };
    if (tree.top.vectors > 0) count(tree.top.vectors);
    subtrees.on_skipped = [&](std::uint64_t id, std::uint64_t n) {
      if (!tree.top.ids.contains(id)) count(n);
    };
    const auto keep = [&](Behaviour&& b) {
      count(b.vectors);
      FoundBehaviour f;
      f.behaviour = std::move(b);
      for (std::size_t i = 0; i < specs.size(); ++i) {
        f.cells.push_back(instance_cells(f.behaviour.results[i], instance_map(i), specs[i]));
      }
      f.behaviour.results.clear();  // formatted; the runs' trajectories are not kept
      f.objective = objective_of(f.cells);
      journal.append(key, f.behaviour, cell_texts(f.cells));
      tables_.admit(f);
      better(f);
      found.push_back(std::move(f));
      (void)past_memory_threshold(guard, found.size());
    };
    if (search_.mode == WeightSearch::Mode::All) {
      out.stats = exact_search(specs, grid_, threads, keep, nullptr, &root, &subtrees, stop);
    } else {
      BranchAndBound bnb;
      bnb.objective = [&](const std::vector<RunResult>& results) {
        return sign * class_objective(results, objective_);
      };
      bnb.lower_bound = [&](std::span<const Simulation> sims) { return class_lower_bound(sims, objective_); };
      bnb.on_pruned = count;
      bnb.on_leaf = [&](const CertifiedLeaf& leaf) {
        if (leaf.kind == CertifiedLeaf::Kind::Beaten) count(leaf.vectors);
        journal.append_leaf(key, leaf);
      };
      const auto better_probe = [&](const SearchProbeLog::Point& at, double objective) {
        if (!(objective < incumbent)) return;
        incumbent = objective;
        best_weights = grid_.weights_at(at);
      };
      const TakenProbes taken = probes_taken_up(key, root, better_probe);
      bnb.probes = spread_probes(grid_, root, search_.probes, id_);
      std::erase_if(bnb.probes, [&](const SearchProbeLog::Point& at) { return taken.points.contains(at); });
      std::optional<SearchProbeLog> probe_log;  // opened only when probes are left to run
      if (!bnb.probes.empty()) probe_log.emplace(out_dir_ + "/" + kSearchProbesFile);
      bnb.incumbent = incumbent;
      bnb.order = search_.order;
      bnb.max_open = search_.max_open;
      bnb.on_probe = [&](const std::array<int, WeightGrid::kMaxWeights>& at, double objective) {
        probe_log->append(key, at, grid_.weights(), sign * objective);
        better_probe(at, objective);
      };
      SearchAnytimeLog anytime(out_dir_, id_, key, grid_.count(root), sign, search_.weights);
      bnb.on_anytime = [&](const AnytimeState& state) {
        anytime.record(state, resolved.load(), best_weights, "running");
      };
      out.stats = exact_search(specs, grid_, threads, keep, &bnb, &root, &subtrees, stop);
      out.stats.probes += taken.points.size();
      out.stats.best_probe = std::min(out.stats.best_probe, taken.best);
      anytime.record(state_at_end(out.stats), resolved.load(), best_weights,
                     out.stats.stopped ? "stopped" : "finished");
      out.standing = describe_search_status(anytime.last(), metric_unit(objective_.column));
    }
    out.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (out.stats.stopped && guard != nullptr && guard->reached())
      return stopped_by_memory(std::move(out), *guard, MemoryStop::Stage::Searching);
    return out;
  }

  /// The rows of the files for the behaviours of the whole grid (one search's, or the shards'
  /// merged by merged()). Mode best keeps the optimal ones (every tie): the others were found
  /// before a better one was.
  /// `journal_dirs`: the directories of the journals that hold its lines (mode best writes its
  /// certificate from them).
  SearchRows rows(Searched searched, const std::vector<std::string>& journal_dirs,
                  const json& shards = nullptr) {
    std::vector<FoundBehaviour>& found = searched.found;
    if (search_.mode == WeightSearch::Mode::Best) {
      const double sign = direction_sign();
      const double optimum = signed_optimum(found);
      std::erase_if(found, [&](const FoundBehaviour& f) { return !(sign * f.objective == optimum); });
      searched.stats.best = optimum;
      for (const FoundBehaviour& f : found) optimal_vectors_ += f.behaviour.vectors;
    }
    SearchRows rows;
    tables_.format(found, instance_specs(), rows);
    rows.record = record(found, searched, shards);
    if (search_.mode == WeightSearch::Mode::Best) {
      rows.record["certificate"].update(write_certificate(journal_dirs, searched.stats.best));
    }
    return rows;
  }

  /// The smallest direction_sign() x objective among `found` (+infinity when none has one): the
  /// optimum that mode best keeps the behaviours of.
  [[nodiscard]] double signed_optimum(const std::vector<FoundBehaviour>& found) const {
    double optimum = std::numeric_limits<double>::infinity();
    for (const FoundBehaviour& f : found) {
      if (!std::isnan(f.objective)) optimum = std::min(optimum, direction_sign() * f.objective);
    }
    return optimum;
  }

  /// The rows of behaviours.csv that rows() formats for `found`: a row per behaviour and
  /// instance, of every behaviour in mode all, of the optimal ones in mode best.
  [[nodiscard]] std::size_t rows_to_format(const std::vector<FoundBehaviour>& found) const {
    std::size_t kept = found.size();
    if (search_.mode == WeightSearch::Mode::Best) {
      const double optimum = signed_optimum(found);
      kept = static_cast<std::size_t>(std::count_if(found.begin(), found.end(), [&](const FoundBehaviour& f) {
        return direction_sign() * f.objective == optimum;
      }));
    }
    return kept * instance_count();
  }

  /// Refuses (ConfigError naming the shard's journal) a finished shard whose journal does not hold
  /// what the shard found: in mode all, behaviours covering the shard's part of the box; in mode
  /// best, a behaviour of the optimum its searches.json `record` gives. A journal emptied,
  /// deleted, cut or replaced (another sweep's lines are not read) after the shard finished would
  /// otherwise merge into wrong files. (In mode best a lost pruned region cannot change the
  /// optimum; the certificate's cover check then says so, as for a journal part of which an
  /// older build wrote.)
  void check_shard_journal(const ShardDir& shard, const Journal& journal, const json& record) const {
    const std::string rerun =
        ": its journal lost lines or was replaced after the shard finished; rerun the "
        "shard (`fsweep run SWEEP --shard " +
        std::to_string(shard.index) + "/" + std::to_string(shard.count) + " --fresh` into " + shard.path +
        ")";
    if (search_.mode == WeightSearch::Mode::All) {
      const std::uint64_t expected = grid_.count(grid_.shard(shard.index, shard.count));
      std::uint64_t held = 0;
      for (const FoundBehaviour& f : journal.found) held += f.behaviour.vectors;
      if (held != expected) {
        throw ConfigError(journal_path(shard.path),
                          "holds search " + std::to_string(id_) + "'s behaviours of " + std::to_string(held) +
                              " of the shard's " + std::to_string(expected) + " weight vectors" + rerun);
      }
      return;
    }
    const json note = record.contains("certificate") ? record.at("certificate") : json();
    const json recorded = note.is_object() ? note.value("optimum", json("missing")) : json("missing");
    if (!recorded.is_null() && !recorded.is_number()) {
      throw ConfigError(shard.path + "/" + kSearchesFile, "search " + std::to_string(id_) +
                                                              "'s certificate.optimum " + recorded.dump() +
                                                              "; allowed: a number or null");
    }
    const double found = signed_optimum(journal.found);
    const bool same =
        recorded.is_null() ? std::isinf(found) : direction_sign() * recorded.get<double>() == found;
    if (!same) {
      throw ConfigError(journal_path(shard.path), "holds no behaviour of search " + std::to_string(id_) +
                                                      " with the optimum " + recorded.dump() +
                                                      " its searches.json records" + rerun);
    }
  }

  /// Adds a shard's searches.json record's counts of work to `out` (merged()).
  void add_shard_counts(Searched& out, const json& r) const {
    out.stats.splits += r.at("splits").get<std::uint64_t>();
    out.stats.forks += r.at("forks").get<std::uint64_t>();
    if (r.contains("steps") && r.at("steps").is_number()) {
      out.stats.steps += r.at("steps").get<std::uint64_t>();
    } else {
      out.steps_known = false;
    }
    out.wall_s += r.at("wall_s").get<double>();
    if (r.contains("probes") && r.at("probes").is_number())
      out.stats.probes += r.at("probes").get<std::size_t>();
    if (r.contains("best_probe") && r.at("best_probe").is_number()) {
      out.stats.best_probe =
          std::min(out.stats.best_probe, direction_sign() * r.at("best_probe").get<double>());
    }
    const json& c = r.at("certificate");
    if (c.is_null()) return;
    out.stats.behaviours += c.at("finished_behaviours").get<std::uint64_t>();
    out.stats.pruned_regions += c.at("pruned_regions").get<std::uint64_t>();
    out.stats.pruned_vectors += c.at("pruned_vectors").get<std::uint64_t>();
    if (!c.at("smallest_pruned_bound").is_null()) {
      out.stats.smallest_pruned_bound = std::min(
          out.stats.smallest_pruned_bound, direction_sign() * c.at("smallest_pruned_bound").get<double>());
    }
  }

  /// The parts of the whole grid's behaviours that searches of its shards found in `dirs`,
  /// merged: behaviours with one trace are one behaviour of the whole search (Behaviour::trace),
  /// its region the union of theirs. `records`: each shard's searches.json record of this search.
  /// `guard` (may be null): the memory guard; once it reached its threshold reading a journal,
  /// the rest is not read and `out` is stopped_by_memory() (stage Merging).
  Searched merged(const std::vector<ShardDir>& shards, const std::vector<json>& records, MemoryWatch* guard) {
    Searched out;
    const std::string key = journal_key();
    std::map<std::uint64_t, std::size_t> by_trace;
    for (std::size_t s = 0; s < shards.size(); ++s) {
      const std::string& dir = shards[s].path;
      Journal journaled = read_journal(key, dir, JournalDamage::Refuse, false, guard);
      if (journaled.empty() && journaled.previous_lines > 0) {
        throw ConfigError(journal_path(dir),
                          "holds the shard's lines of search " + std::to_string(id_) +
                              " in journal format '" + std::string(SearchJournal::kPreviousFormat) +
                              "' of an older build, whose region tree differs; this build merges '" +
                              std::string(SearchJournal::kFormat) +
                              "' only: rerun the shard's `fsweep run --shard i/N` with this build, after "
                              "deleting its searches.json");
      }
      if (guard == nullptr || !guard->reached()) check_shard_journal(shards[s], journaled, records[s]);
      std::vector<FoundBehaviour> read = std::move(journaled.found);
      if (guard != nullptr && guard->reached()) {
        out.found.insert(out.found.end(), std::make_move_iterator(read.begin()),
                         std::make_move_iterator(read.end()));
        return stopped_by_memory(std::move(out), *guard, MemoryStop::Stage::Merging);
      }
      for (FoundBehaviour& f : read) {
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
    for (FoundBehaviour& f : out.found) {
      vectors += f.behaviour.vectors;
      tables_.admit(f);
    }
    if (search_.mode == WeightSearch::Mode::All && vectors != grid_.size()) {
      throw ConfigError(journal_path(shards.front().path),
                        "the shards' journals hold the behaviours of " + std::to_string(vectors) +
                            " of the search's " + std::to_string(grid_.size()) +
                            " weight vectors; rerun the shards that lack some");
    }
    for (std::size_t s = 0; s < records.size(); ++s) {
      try {
        add_shard_counts(out, records[s]);
      } catch (const json::exception& e) {
        throw ConfigError(shards[s].path + "/" + kSearchesFile,
                          "search " + std::to_string(id_) + "'s record: " + e.what());
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

  /// Where a search of mode best stands at its end (stopped or finished).
  [[nodiscard]] static AnytimeState state_at_end(const ExactSearchStats& stats) {
    AnytimeState last;
    last.best = stats.best;
    last.lower = std::min(stats.best, stats.unresolved_bound);
    last.open_branches = stats.unresolved_branches;
    return last;
  }

  /// The stderr note of a resumed search whose journal holds only `lines` lines of it in the
  /// previous journal format (not read: their region tree differs).
  void note_previous_format(std::size_t lines) const {
    std::fprintf(stderr,
                 "fsweep: %s holds %zu lines of search %zu in journal format '%s' of an older build, "
                 "whose region tree differs; this build does not read them, and the search starts again\n",
                 journal_path(out_dir_).c_str(), lines, id_,
                 std::string(SearchJournal::kPreviousFormat).c_str());
  }

  /// Probes taken up from a stopped run's log: their points, and the best of their objectives
  /// as the search compares them (direction_sign() applied; +infinity: none).
  struct TakenProbes {
    std::set<SearchProbeLog::Point> points;
    double best = std::numeric_limits<double>::infinity();
  };

  /// The probes search `key` finished in a stopped run (search_probes.jsonl) that lie in `root`,
  /// each once: given to `taken` with its objective as the search compares it (NaN: none), to be
  /// taken up instead of run again.
  [[nodiscard]] TakenProbes probes_taken_up(
      const std::string& key, const WeightRegion& root,
      const std::function<void(const SearchProbeLog::Point&, double)>& taken) const {
    TakenProbes out;
    for (const SearchProbeLog::Probe& p :
         SearchProbeLog::read(out_dir_ + "/" + kSearchProbesFile, key, grid_.weights())) {
      if (!grid_.contains(root, p.at) || !out.points.insert(p.at).second) continue;
      const double objective = direction_sign() * p.objective;
      out.best = std::min(out.best, objective);  // NaN: none
      taken(p.at, objective);
    }
    return out;
  }

  /// The journal of finished behaviours in `dir`, shared by the sweep's searches.
  [[nodiscard]] static std::string journal_path(const std::string& dir) {
    return dir + "/" + kSearchJournalFile;
  }

  /// What a journal line must match to be this search's: its instances (every resolved
  /// parameter), box, objective and mode, and the journal's `format` (SearchJournal::format_for()).
  /// This search's key in its journal format (SearchJournal::format_for()).
  [[nodiscard]] std::string journal_key() const {
    return unit_key(instance_count(), SearchJournal::format_for(instance_count()));
  }
  [[nodiscard]] std::string unit_key(std::size_t instances, std::string_view format) const {
    json key = json::array();
    for (std::size_t i = 0; i < instances; ++i) key.push_back(plan_.search_instance_json(unit_, i));
    key.push_back(search_.values);
    key.push_back(std::string(objective_.name));
    key.push_back(search_.mode == WeightSearch::Mode::All ? "all" : "best");
    key.push_back(std::string(format));
    return sweep_hash(key);  // the FNV-1a 64 of its dump, as the manifest's hash of a sweep
  }

  /// The class mean of the objective's cells.
  [[nodiscard]] double objective_of(const std::vector<Columns>& cells) const {
    double sum = 0.0;
    for (const Columns& c : cells) {
      const auto it =
          std::find_if(c.begin(), c.end(), [&](const auto& cell) { return cell.first == objective_.column; });
      sum += it == c.end() ? std::numeric_limits<double>::quiet_NaN() : metric_number(it->second);
    }
    return sum / static_cast<double>(cells.size());
  }

  /// This search's behaviours and finished subtrees in the journal of `dir` (SearchJournal::read():
  /// `damage` Repair for a search about to append to its own journal, Refuse for a merge reading a
  /// finished shard's). `admitting`: each behaviour goes through admit() as it is read (a resumed
  /// search's own journal; a merge admits the behaviours the shards' parts make up). `guard`: the
  /// memory guard of a resumed search; once the memory reaches its threshold, the behaviours
  /// read after are dropped (the read goes on to the end: stopped early, it would cut the journal
  /// as damaged there).
  [[nodiscard]] Journal read_journal(const std::string& key, const std::string& dir, JournalDamage damage,
                                     bool admitting, MemoryWatch* guard = nullptr) {
    Journal out;
    const Columns names = cell_names();
    const std::string_view hint =
        "; the shard's journal is damaged: delete its searches.json and rerun its `fsweep run --shard i/N`, "
        "which keeps the lines before this one and redoes the rest";
    std::size_t read = 0;
    const auto behaviour = [&](JournaledBehaviour&& journaled) {
      if (past_memory_threshold(guard, ++read)) return;
      FoundBehaviour f;
      f.behaviour = std::move(journaled.behaviour);
      for (std::vector<std::string>& row : journaled.cells) {
        Columns c = names;
        for (std::size_t m = 0; m < c.size(); ++m) c[m].second = std::move(row[m]);
        f.cells.push_back(std::move(c));
      }
      f.objective = objective_of(f.cells);
      if (admitting) tables_.admit(f);
      out.found.push_back(std::move(f));
    };
    const auto leaf = [&](JournaledLeaf&& l) {
      SubtreeTally t;
      t.vectors = l.vectors;
      if (l.kind == CertifiedLeaf::Kind::Pruned) {
        t.pruned_regions = 1;
        t.pruned_vectors = l.vectors;
        t.smallest_pruned_bound = l.value;
      } else {
        t.behaviours = 1;
      }
      out.leaves.emplace_back(std::move(l.choices), t);
    };
    out.done = SearchJournal::read(journal_path(dir), journal_shape(key, names), damage, hint, behaviour,
                                   leaf, &out.previous_lines);
    return out;
  }

  /// The columns of a behaviour's cells per instance.
  [[nodiscard]] Columns cell_names() const {
    return instance_cells(RunResult{}, plan_.maps().at(unit_.maps.front()), plan_.search_instance(unit_, 0));
  }
  [[nodiscard]] JournalShape journal_shape(const std::string& key, const Columns& names) const {
    JournalShape shape{key, &grid_, instance_count(), names.size()};
    // A class's lines of the format before name regions of another tree: counted, not read.
    if (instance_count() > 1 && SearchJournal::format_for(instance_count()) != SearchJournal::kPreviousFormat)
      shape.counted_key = unit_key(instance_count(), SearchJournal::kPreviousFormat);
    // Journals written before runs had a coverage target lack that column; its cells are empty.
    const auto added = std::find_if(names.begin(), names.end(), [](const auto& column) {
      return column.first == "distance_to_coverage_target_m";
    });
    if (added != names.end()) shape.added_cell = static_cast<std::size_t>(added - names.begin());
    return shape;
  }

  /// Mode best: writes the certificate of the whole search from the journals in `dirs` (its own,
  /// or its shards') and returns its note for searches.json (null in mode all).
  [[nodiscard]] json write_certificate(const std::vector<std::string>& dirs, double optimum) const {
    if (search_.mode != WeightSearch::Mode::Best) return nullptr;
    CertificateSource source;
    for (const std::string& dir : dirs) source.journals.push_back(journal_path(dir));
    const Columns names = cell_names();
    source.shape = journal_shape(journal_key(), names);
    source.objective_cell =
        static_cast<std::size_t>(std::find_if(names.begin(), names.end(),
                                              [&](const auto& c) { return c.first == objective_.column; }) -
                                 names.begin());
    source.sign = direction_sign();
    json instances = json::array();
    for (std::size_t i = 0; i < instance_count(); ++i)
      instances.push_back(plan_.search_instance_json(unit_, i));
    const json header{{"format", kCertificateFormat},
                      {kSearchIdColumn, id_},
                      {"strategy_label", plan_.strategies().at(unit_.entry).label},
                      {"map_class", unit_.map_class},
                      {"weights", search_.weights},
                      {"values", search_.values},
                      {"objective", std::string(objective_.name)},
                      {"objective_column", objective_.column},
                      {"direction", objective_.direction == Direction::Minimize ? "minimize" : "maximize"},
                      {"optimum", std::isfinite(optimum) ? json(direction_sign() * optimum) : json(nullptr)},
                      {"vectors", grid_.size()},
                      {"instances", instances}};
    return write_search_certificate(out_dir_ + "/" + search_certificate_file(id_), header, source);
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
  [[nodiscard]] json record(const std::vector<FoundBehaviour>& found, const Searched& searched,
                            const json& shards) const {
    const ExactSearchStats& stats = searched.stats;
    json box = json::object();
    for (std::size_t k = 0; k < search_.weights.size(); ++k) box[search_.weights[k]] = search_.values[k];
    json specs = json::array();
    for (std::size_t i = 0; i < instance_count(); ++i) specs.push_back(plan_.search_instance_json(unit_, i));
    std::vector<std::string> maps;
    for (const std::size_t m : unit_.maps) maps.push_back(plan_.maps().at(m).label);
    return json{{kSearchIdColumn, id_},
                {"strategy_label", plan_.strategies().at(unit_.entry).label},
                {"map_class", unit_.map_class},
                {"maps", maps},
                {"repetitions", plan_.repetitions()},
                {"planner", planner_label(plan_.planners().at(unit_.planner))},
                {"robot", plan_.robots().at(unit_.robot).label},
                {"mode", search_.mode == WeightSearch::Mode::All ? "all" : "best"},
                {"order", search_.mode == WeightSearch::Mode::All ? json(nullptr) : json(order_name())},
                {"probes", search_.mode == WeightSearch::Mode::All ? json(nullptr) : json(stats.probes)},
                {"best_probe", search_.mode == WeightSearch::Mode::All || !std::isfinite(stats.best_probe)
                                   ? json(nullptr)
                                   : json(direction_sign() * stats.best_probe)},
                {"objective", std::string(objective_.name)},
                {"box", box},
                {"vectors", grid_.size()},
                {"behaviours", found.size()},
                {"distinct_outcomes", distinct_outcomes(found)},
                {"resumed_behaviours", searched.resumed},
                {"splits", stats.splits},
                {"forks", stats.forks},
                {"steps", searched.steps_known ? json(stats.steps) : json(nullptr)},
                {"certificate", certificate(stats)},
                {"wall_s", searched.wall_s},
                {"merged_from_shards", shards},
                {"instances", specs}};
  }

  /// Mode best's order of exploration ("order" in the sweep file).
  [[nodiscard]] std::string order_name() const {
    return search_.order == SearchOrder::Depth ? "depth"
                                               : "bound (max_open " + std::to_string(search_.max_open) + ")";
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
  std::size_t id_;
  const WeightSearch& search_;
  const Objective& objective_;
  SearchTables tables_;
  const WeightGrid& grid_;
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

/// Mode best: each search's status joined from its shards' (join_search_status()), written as
/// out_dir's status file; returns a note for the error of a merge that lacks some shard (empty
/// when no search has a status). `merged`: every shard finished, and a search some of whose
/// shards have no status (run by an older fsweep) gets none.
std::string join_shard_status(const SweepPlan& plan, const std::vector<SearchUnit>& units,
                              const std::string& out_dir, const std::vector<std::string>& shard_dirs,
                              bool merged = false) {
  std::string note;
  const Objective* objective = find_objective(plan.objective());
  const double sign = objective->direction == Direction::Minimize ? 1.0 : -1.0;
  for (std::size_t id = 0; id < units.size(); ++id) {
    if (plan.strategies().at(units[id].entry).search->mode != WeightSearch::Mode::Best) continue;
    std::vector<json> shards;
    for (const std::string& dir : shard_dirs) {
      const std::string path = dir + "/" + search_status_file(id);
      json status = nullptr;
      if (const auto text = read_file(path)) {
        try {
          status = parse_json_bounded(*text, path);
        } catch (const std::exception&) {  // an unreadable status: that shard's bound is unknown
          status = nullptr;
        }
      }
      shards.push_back(std::move(status));
    }
    if (merged && std::find(shards.begin(), shards.end(), json(nullptr)) != shards.end()) continue;
    const WeightGrid grid(plan.strategies().at(units[id].entry).search->values);
    const json joint = join_search_status(shards, grid.size(), sign);
    std::filesystem::create_directories(out_dir);
    write_file_atomically(out_dir + "/" + search_status_file(id), joint.dump(2) + '\n');
    note += "; search " + std::to_string(id) +
            " of the shards so far: " + describe_search_status(joint, metric_unit(objective->column)) + " (" +
            out_dir + "/" + search_status_file(id) + ")";
  }
  return note;
}

/// Throws ConfigError, before anything is searched, when the part of search `u`'s box that shard
/// `shard_index` of `shard_count` searches holds more than WeightGrid::kMaxSearchBlocks blocks:
/// a decision over the whole part holds memory per block.
void check_search_blocks(const WeightGrid& grid, const SearchUnit& u, std::uint64_t shard_index,
                         std::uint64_t shard_count) {
  if (const std::uint64_t blocks = WeightGrid::shard_blocks(grid.block_count(), shard_index, shard_count);
      blocks > WeightGrid::kMaxSearchBlocks) {
    const std::uint64_t shards =
        (grid.block_count() + WeightGrid::kMaxSearchBlocks - 1) / WeightGrid::kMaxSearchBlocks;
    throw ConfigError(
        "/strategies/" + std::to_string(u.entry) + "/params",
        "the part of the search box this process searches holds " + sweep_detail::with_thousands(blocks) +
            " blocks of 8 values per weight; allowed: at most " +
            sweep_detail::with_thousands(WeightGrid::kMaxSearchBlocks) +
            " per process (4 times the full [0, 250]^4 of integers), since a decision over them "
            "holds memory for each block: search it in at least " +
            std::to_string(shards) +
            " shards (fsweep run --shard i/N, or fsweep slurm) or with fewer values");
  }
}

}  // namespace

SearchRunReport run_weight_searches(const SweepPlan& plan, const std::string& out_dir, int threads,
                                    bool progress, std::uint64_t shard_index, std::uint64_t shard_count,
                                    const std::atomic<bool>* stop, const SearchMemoryGuard& memory) {
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
    check_search_blocks(grid, u, shard_index, shard_count);
    roots.push_back(shard_count > 1 ? grid.shard(shard_index, shard_count) : grid.everything());
    total += grid.count(roots.back());
  }
  ProgressMeter meter(total, "weight vectors", progress);
  // One memory guard for the searches; its flag, which they poll, forwards `stop`.
  std::optional<MemoryWatch> guard;
  if (memory.limit) guard.emplace(memory.limit->bytes, memory_reader(memory), stop);
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
        roots[id], guard ? guard->stop() : stop, guard ? &*guard : nullptr);
    // A stop (Ctrl-C, the memory guard) ends the searches; `memory_stop`: the guard's.
    const auto stopped = [&](std::optional<MemoryStop> memory_stop) {
      meter.finish(done, 0);
      if (progress) {
        std::fputs("fsweep: weight search stopped; what it finished is in search_journal.jsonl\n", stderr);
      }
      report.interrupted = true;
      if (memory_stop) {
        MemoryStop& s = report.memory_stop.emplace(std::move(*memory_stop));
        s.search_id = id;
        s.limit = *memory.limit;
        s.message = describe_memory_stop(s, *plan.strategies().at(units[id].entry).search);
      }
      report.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    if (searched.stats.stopped) {
      stopped(std::move(searched.memory_stop));
      if (!searched.standing.empty()) {
        report.standings.push_back("search " + std::to_string(id) + ": " + searched.standing + " (" +
                                   search_status_file(id) + ")");
      }
      return report;
    }
    if (shard_count > 1) {
      shard_records.push_back(writer.shard_record(searched, shard_index, shard_count));
      continue;
    }
    // Its files' text, formatted beside the behaviours, may be what reaches the limit: stop
    // before formatting when the estimate passes it, after when the formatting did (the journal
    // holds the finished search; no other search file is written).
    const std::size_t held = searched.found.size();
    if (std::optional<MemoryStop> s =
            formatting_would_pass(guard ? &*guard : nullptr, memory, held,
                                  writer.rows_to_format(searched.found), MemoryStop::Stage::Writing)) {
      stopped(std::move(s));
      return report;
    }
    rows.push_back(writer.rows(std::move(searched), {out_dir}));
    if (guard && (guard->reached() || guard->check())) {
      MemoryStop s;
      s.in_use_bytes = guard->reached().value_or(0);
      s.held_behaviours = held;
      s.stage = MemoryStop::Stage::Writing;
      stopped(std::move(s));
      return report;
    }
  }
  meter.finish(done, 0);
  if (shard_count > 1) {
    // A shard's searches are parts: merge_weight_searches() writes the files. Its searches.json
    // marks it complete.
    write_file_atomically(out_dir + "/" + kSearchesFile, json{{"searches", shard_records}}.dump(2) + '\n');
    report.files.emplace_back(kSearchesFile);
    report.searches = units.size();
    report.vectors = total;  // the shard's own part of the boxes
  } else {
    write_search_files(plan, units, std::move(rows), out_dir, report);
  }
  report.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

std::vector<std::pair<std::uint64_t, std::uint64_t>> weight_search_blocks(const SweepPlan& plan) {
  std::vector<std::pair<std::uint64_t, std::uint64_t>> out;
  for (const SearchUnit& u : plan.search_units()) {
    const WeightGrid grid(plan.strategies().at(u.entry).search->values);
    out.emplace_back(grid.size(), grid.block_count());
  }
  return out;
}

std::string join_search_statuses(const SweepPlan& plan, const std::string& out_dir,
                                 const std::vector<std::string>& shard_dirs) {
  const Objective* objective = nullptr;
  const std::vector<SearchUnit> units = checked_units(plan, objective);
  return join_shard_status(plan, units, out_dir, shard_dirs);
}

SearchRunReport merge_weight_searches(const SweepPlan& plan, const std::string& out_dir,
                                      const std::vector<ShardDir>& shards, const SearchMemoryGuard& memory) {
  SearchRunReport report;
  const Objective* objective = nullptr;
  const std::vector<SearchUnit> units = checked_units(plan, objective);
  if (units.empty()) return report;
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::string> shard_dirs;
  shard_dirs.reserve(shards.size());
  for (const ShardDir& shard : shards) shard_dirs.push_back(shard.path);
  // Each shard's record of each search: its searches.json says the shard's searches finished.
  std::vector<std::vector<json>> records(units.size());
  for (const ShardDir& at : shards) {
    const std::string& dir = at.path;
    const std::string path = dir + "/" + kSearchesFile;
    const std::optional<std::string> text = read_file(path);
    if (!text) {
      throw ConfigError(path,
                        "missing: the shard's weight searches did not finish; rerun `fsweep run --shard` "
                        "for it (it resumes from its search_journal.jsonl)" +
                            join_shard_status(plan, units, out_dir, shard_dirs));
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
    for (std::size_t id = 0; id < units.size(); ++id) {
      const json& r = records[id].back();
      const json recorded = r.is_object() ? r.value("shard", json()) : json();
      const json expected{{"index", at.index}, {"count", at.count}};
      if (recorded != expected) {
        throw ConfigError(path, "search " + std::to_string(id) + " is of shard " + recorded.dump() +
                                    ", its directory's name says " + expected.dump() +
                                    ": a shard copied or renamed; rerun `fsweep run SWEEP --shard " +
                                    std::to_string(at.index) + "/" + std::to_string(at.count) +
                                    " --fresh` into " + dir);
      }
    }
  }
  std::optional<MemoryWatch> guard;
  if (memory.limit) guard.emplace(memory.limit->bytes, memory_reader(memory), nullptr);
  const auto stopped = [&](std::size_t id, MemoryStop s) {
    s.search_id = id;
    s.limit = *memory.limit;
    s.stage = MemoryStop::Stage::Merging;
    s.message = describe_memory_stop(s, *plan.strategies().at(units[id].entry).search);
    report.memory_stop = std::move(s);
    report.interrupted = true;
    return report;
  };
  std::vector<SearchRows> rows;
  for (std::size_t id = 0; id < units.size(); ++id) {
    SearchWriter writer(plan, units[id], id, *objective, out_dir);
    Searched merged = writer.merged(shards, records[id], guard ? &*guard : nullptr);
    if (merged.memory_stop) return stopped(id, std::move(*merged.memory_stop));
    if (std::optional<MemoryStop> s =
            formatting_would_pass(guard ? &*guard : nullptr, memory, merged.found.size(),
                                  writer.rows_to_format(merged.found), MemoryStop::Stage::Merging)) {
      return stopped(id, std::move(*s));
    }
    rows.push_back(writer.rows(std::move(merged), shard_dirs, json(records[id])));
  }
  (void)join_shard_status(plan, units, out_dir, shard_dirs, true);  // every shard finished: the optimum
  write_search_files(plan, units, std::move(rows), out_dir, report);
  report.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

std::string weight_search_journal_key(const SweepPlan& plan, std::size_t search_id, std::string_view format) {
  const Objective* objective = nullptr;
  const std::vector<SearchUnit> units = checked_units(plan, objective);
  const SearchWriter writer(plan, units.at(search_id), search_id, *objective, std::string());
  return writer.unit_key(writer.instance_count(), format);
}

}  // namespace sweep
}  // namespace fsweep
