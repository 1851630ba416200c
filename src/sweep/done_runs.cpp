#include "sweep/done_runs.hpp"

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>

#include "core/config_error.hpp"
#include "core/csv_reader.hpp"
#include "core/files.hpp"
#include "core/json_excerpt.hpp"
#include "core/random.hpp"
#include "report/runs_schema.hpp"
#include "report/search_schema.hpp"
#include "sweep/csv_journal.hpp"
#include "sweep/manifest.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_table.hpp"

namespace fsweep {
inline namespace sweep {

namespace fs = std::filesystem;

void DoneRuns::add(std::uint64_t key, std::uint64_t index) { rows_.push_back({index, key}); }

void DoneRuns::seal() { std::sort(rows_.begin(), rows_.end()); }

namespace {

auto find_index(const std::vector<DoneRuns::Row>& rows, std::uint64_t index) {
  return std::lower_bound(rows.begin(), rows.end(), index,
                          [](const DoneRuns::Row& r, std::uint64_t i) { return r.index < i; });
}

}  // namespace

bool DoneRuns::contains(std::uint64_t key, std::uint64_t index) const {
  const auto it = find_index(rows_, index);
  return it != rows_.end() && it->index == index && it->key == key;
}

bool DoneRuns::has(std::uint64_t index) const {
  const auto it = find_index(rows_, index);
  return it != rows_.end() && it->index == index;
}

RunPlacement::RunPlacement(const DoneRuns& done) {
  rows_.reserve(done.size());
  for (const DoneRuns::Row& r : done.rows()) rows_.push_back({r.key, r.index, kNowhere});
  std::sort(rows_.begin(), rows_.end(),
            [](const Move& a, const Move& b) { return a.key != b.key ? a.key < b.key : a.from < b.from; });
}

void RunPlacement::offer(std::uint64_t index, std::uint64_t key) {
  auto it = std::lower_bound(rows_.begin(), rows_.end(), key,
                             [](const Move& m, std::uint64_t k) { return m.key < k; });
  while (it != rows_.end() && it->key == key && it->to != kNowhere) ++it;  // rows of one key in order
  if (it == rows_.end() || it->key != key) return;
  it->to = index;
  ++placed_;
}

void RunPlacement::seal() {
  std::sort(rows_.begin(), rows_.end(), [](const Move& a, const Move& b) { return a.from < b.from; });
  arrived_.clear();
  arrived_.reserve(placed_);
  for (const Move& m : rows_) {
    if (m.to != kNowhere) arrived_.push_back({m.to, m.key});
  }
  std::sort(arrived_.begin(), arrived_.end());
}

std::optional<std::uint64_t> RunPlacement::new_index(std::uint64_t key, std::uint64_t index) const {
  const auto from = std::lower_bound(rows_.begin(), rows_.end(), index,
                                     [](const Move& m, std::uint64_t i) { return m.from < i; });
  if (from != rows_.end() && from->from == index && from->key == key) {
    if (from->to != kNowhere) return from->to;
    return std::nullopt;
  }
  if (std::binary_search(arrived_.begin(), arrived_.end(), DoneRuns::Row{index, key})) return index;
  return std::nullopt;
}

std::vector<DoneRuns::Row> RunPlacement::unplaced() const {
  std::vector<DoneRuns::Row> out;
  for (const Move& m : rows_) {
    if (m.to == kNowhere) out.push_back({m.from, m.key});
  }
  return out;
}

namespace {

/// A cell quoted in a message: at most 40 characters, non-printable bytes as '?'.
std::string quoted_cell(std::string_view cell) {
  constexpr std::size_t kMax = 40;
  std::string out = "'";
  for (const char c : cell.substr(0, kMax)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
  out += cell.size() > kMax ? "...'" : "'";
  return out;
}

std::string field_count_reason(std::size_t got, std::size_t expected) {
  return "the line has " + std::to_string(got) + (got == 1 ? " field" : " fields") +
         ", where the header has " + std::to_string(expected);
}

/// Tells on stderr every line repair() dropped, and why.
void report_dropped(const CsvJournal& journal, const CsvRepairStats& stats, const char* what) {
  for (const CsvDroppedLines& d : stats.dropped_lines) {
    std::fprintf(stderr, "fsweep: dropped %s: %s\n", d.describe(journal.path()).c_str(), what);
  }
}

/// Refuses done rows whose run_key is not the key `plan` gives their run_index: their inputs
/// changed since they ran (a map file edited: run keys cover the map's content; or keys of
/// another fsweep version), so they are not this sweep's results. Keys are computed in parallel.
void verify_done_keys(const SweepPlan& plan, const DoneRuns& done, const std::string& runs_path) {
  const std::vector<DoneRuns::Row>& rows = done.rows();
  std::vector<std::uint64_t> expected(rows.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows.size()), [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      expected[i] = parse_run_key(plan.run_key(rows[i].index)).value_or(0);
    }
  });
  std::size_t stale = 0;
  std::string examples;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].key == expected[i]) continue;
    if (++stale <= 3) {
      examples += (stale > 1 ? "; run " : "run ") + std::to_string(rows[i].index) + ": " +
                  hex64(rows[i].key) + " in the file, " + hex64(expected[i]) + " now";
    }
  }
  if (stale == 0) return;
  throw ConfigError(runs_path, std::to_string(stale) + " of its " + std::to_string(rows.size()) +
                                   " runs have another run_key than this sweep gives them (" + examples +
                                   "): their inputs changed since they ran (an edited map file, or keys of "
                                   "another fsweep version); use --fresh to start over, or another output "
                                   "directory");
}

/// What a runs.csv row must be to be kept by repair_runs(): its field count and the positions of
/// its run_key, run_index and end_reason; a run_index below `run_count` and of the shard.
struct RowRules {
  std::size_t fields = 0;
  std::size_t key_col = 0;
  std::size_t index_col = 0;
  std::size_t end_col = 0;
  std::uint64_t run_count = UINT64_MAX;  ///< not known: any run_index
  ShardOf shard;
};

/// Repairs runs.csv (CsvJournal::repair()): keeps the rows `rules` accept, each run_index once,
/// and returns them as the done runs. `check` sees the done runs after the scan and before the
/// file is touched (it refuses by throwing).
Resumed repair_runs(const RowRules& rules, CsvJournal& runs,
                    const std::function<void(const DoneRuns&)>& check) {
  Resumed r;
  const std::string error(to_string(EndReason::Error));
  std::vector<bool> seen;  // by run_index / shard count: a row for it was kept
  const CsvRepairStats run_stats = runs.repair(
      [&](const std::vector<std::string>& f) -> std::string {
        if (f.size() != rules.fields) return field_count_reason(f.size(), rules.fields);
        const auto key = parse_run_key(f[rules.key_col]);
        if (!key) return "its run_key " + quoted_cell(f[rules.key_col]) + " is not 16 hexadecimal digits";
        const auto index = parse_run_index(f[rules.index_col]);
        if (!index) return "its run_index " + quoted_cell(f[rules.index_col]) + " is not a whole number";
        if (*index >= rules.run_count) {
          return "its run_index " + f[rules.index_col] + " is not below the sweep's " +
                 std::to_string(rules.run_count) + " runs";
        }
        if (*index % rules.shard.count != rules.shard.index) {
          return "its run_index " + f[rules.index_col] + " is not of shard " +
                 std::to_string(rules.shard.index) + "/" + std::to_string(rules.shard.count);
        }
        const auto slot = static_cast<std::size_t>(*index / rules.shard.count);
        if (slot >= seen.size()) seen.resize(slot + 1, false);
        if (seen[slot]) return "run " + f[rules.index_col] + " has a row earlier in the file";
        seen[slot] = true;
        r.done.add(*key, *index);
        if (r.last_index && *index < *r.last_index) r.in_order = false;
        r.last_index = std::max(r.last_index.value_or(0), *index);
        if (f[rules.end_col] == error) ++r.failed;
        return {};
      },
      [&] {
        r.done.seal();
        check(r.done);  // refuses before runs.csv is touched
      });
  report_dropped(runs, run_stats, "its run is done again (if it is this sweep's), in run order");
  return r;
}

/// Repairs progress.csv: keeps the rows of the runs `is_done` says have a complete runs.csv row.
void repair_progress(CsvJournal& progress,
                     const std::function<bool(std::uint64_t key, std::uint64_t index)>& is_done) {
  const std::size_t key_col = SweepTable::progress_column(kRunKeyColumn);
  const std::size_t index_col = SweepTable::progress_column(kRunIndexColumn);
  const CsvRepairStats stats = progress.repair([&](const std::vector<std::string>& f) -> std::string {
    if (f.size() != SweepTable::kProgressFields)
      return field_count_reason(f.size(), SweepTable::kProgressFields);
    const auto key = parse_run_key(f[key_col]);
    if (!key) return "its run_key " + quoted_cell(f[key_col]) + " is not 16 hexadecimal digits";
    const auto index = parse_run_index(f[index_col]);
    if (!index) return "its run_index " + quoted_cell(f[index_col]) + " is not a whole number";
    if (!is_done(*key, *index)) {
      return "run " + std::to_string(*index) + " (run_key " + f[key_col] +
             ") has no complete row in runs.csv (it did not finish, or its row was dropped)";
    }
    return {};
  });
  report_dropped(progress, stats, "its run's progress is written again with the run");
}

/// True when `sweep` (a manifest's copy of a sweep file) has a strategy entry with an exact
/// weight search.
bool has_search_entry(const nlohmann::json& sweep) {
  if (!sweep.is_object() || !sweep.contains("strategies") || !sweep["strategies"].is_array()) return false;
  const nlohmann::json& entries = sweep["strategies"];
  return std::any_of(entries.begin(), entries.end(),
                     [](const nlohmann::json& e) { return e.is_object() && e.contains("search"); });
}

/// Offers `placement` the runs of `plan` of the shard (`in_shard`) or of the other shards in
/// index order, their keys computed in parallel a block at a time, until every done run has its
/// place; then seals it.
void offer_runs(const SweepPlan& plan, ShardOf shard, bool in_shard, RunPlacement& placement) {
  constexpr std::size_t kBlock = 4096;
  const std::uint64_t n = plan.run_count();
  std::vector<std::uint64_t> indices;
  std::vector<std::uint64_t> keys;
  std::uint64_t next = in_shard ? shard.index : 0;
  while (next < n && !placement.complete()) {
    indices.clear();
    for (; next < n && indices.size() < kBlock; next += in_shard ? shard.count : 1) {
      if (in_shard || next % shard.count != shard.index) indices.push_back(next);
    }
    keys.resize(indices.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, indices.size()), [&](const auto& range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        keys[i] = parse_run_key(plan.run_key(indices[i])).value_or(0);
      }
    });
    for (std::size_t i = 0; i < indices.size(); ++i) placement.offer(indices[i], keys[i]);
  }
  placement.seal();
}

/// A done run of the earlier sweep `old_plan` (rebuilt from the manifest) for a message: "run 17
/// (map 'rooms seed=1', strategy 'EA free' {"w1":10}, repetition 2)"; "run 17 (run_key K)"
/// without the plan.
std::string describe_old_run(const SweepPlan* old_plan, const DoneRuns::Row& row) {
  const std::string run = "run " + std::to_string(row.index);
  if (old_plan == nullptr || row.index >= old_plan->run_count())
    return run + " (run_key " + hex64(row.key) + ")";
  const RunCoordinates c = old_plan->coordinates(row.index);
  const StrategyEntry& entry = old_plan->strategies()[c.strategy_entry];
  const nlohmann::json params = entry.params_at(c.strategy_combo);
  std::string out = run + " (map '" + old_plan->maps()[c.map].label + "', strategy '" + entry.label + "'";
  if (!params.is_null()) out += " " + json_excerpt(params);
  if (old_plan->planners().size() > 1) out += ", planner " + old_plan->planners()[c.planner].name;
  if (old_plan->robots().size() > 1) out += ", robot " + old_plan->robots()[c.robot].label;
  return out + ", repetition " + std::to_string(c.repetition) + ")";
}

/// Throws the ConfigError of an output directory whose finished runs do not all have a place in
/// the shard of the changed sweep `plan` (`placement`, sealed): how many, one or two of them
/// described by the earlier sweep, and what to do. `changed` begins the message.
[[noreturn]] void refuse_unplaced(const SweepPlan& plan, ShardOf shard, const nlohmann::json& old,
                                  const RunPlacement& placement, std::size_t done, const std::string& dir,
                                  const std::string& changed) {
  const std::vector<DoneRuns::Row> missing = placement.unplaced();
  // The shard's runs that are runs of other shards now, and those not in the sweep at all.
  DoneRuns rest;
  for (const DoneRuns::Row& m : missing) rest.add(m.key, m.index);
  rest.seal();
  RunPlacement elsewhere(rest);
  if (shard.count > 1) {
    offer_runs(plan, shard, false, elsewhere);
  } else {
    elsewhere.seal();
  }
  const std::vector<DoneRuns::Row> gone = elsewhere.unplaced();
  const std::string of_done = " of its " + std::to_string(done) + " finished runs";
  if (gone.empty()) {
    const DoneRuns::Row& m = missing.front();
    const std::uint64_t now = elsewhere.new_index(m.key, m.index).value_or(0);
    throw ConfigError(dir,
                      changed + ", in which " + std::to_string(missing.size()) + of_done +
                          " belong to other shards (run indices change with the sweep: run " +
                          std::to_string(m.index) + " is run " + std::to_string(now) + " now, of shard " +
                          std::to_string(now % shard.count) + "/" + std::to_string(shard.count) +
                          "), and a shard directory keeps only its shard's runs; extend the merged results "
                          "instead (fsweep merge, then fsweep run with --out the merged directory), or use "
                          "--fresh to run the shards over");
  }
  std::optional<SweepPlan> old_plan;
  try {
    if (old.contains("sweep"))
      old_plan.emplace(SweepPlan::from_json(old["sweep"], old.value("sweep_file", "")));
  } catch (const std::exception&) {  // NOLINT(bugprone-empty-catch): the runs are named by index and key
  }
  std::string examples;
  for (std::size_t i = 0; i < gone.size() && i < 2; ++i) {
    examples += (i > 0 ? "; " : "") + describe_old_run(old_plan ? &*old_plan : nullptr, gone[i]);
  }
  if (gone.size() > 2) examples += "; ...";
  throw ConfigError(
      dir, changed + ", which does not have " + std::to_string(gone.size()) + of_done + " (" + examples +
               "): a sweep is extended only by adding runs (repetitions, seeds, values, maps or "
               "strategy entries), not by removing or changing finished ones; use --fresh to start "
               "over, or another output directory");
}

}  // namespace

Resumed repair_outputs(const SweepPlan& plan, ShardOf shard, const SweepTable& table, CsvJournal& runs,
                       CsvJournal& progress) {
  const RowRules rules{table.columns().size(),
                       table.column(kRunKeyColumn),
                       table.column(kRunIndexColumn),
                       table.column(kEndReasonColumn),
                       plan.run_count(),
                       shard};
  Resumed r =
      repair_runs(rules, runs, [&](const DoneRuns& done) { verify_done_keys(plan, done, runs.path()); });
  repair_progress(progress,
                  [&](std::uint64_t key, std::uint64_t index) { return r.done.contains(key, index); });
  return r;
}

bool has_rows(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  return std::getline(in, line) && std::getline(in, line);
}

namespace {

constexpr const char* kStartOver = "; use --fresh to start over, or another output directory";

/// The columns of a runs.csv to extend: its header's names and where its key, index and
/// end_reason are.
struct OldColumns {
  std::vector<std::string> names;
  std::size_t key = 0;
  std::size_t index = 0;
  std::size_t end = 0;
};

/// The columns of `header` (runs.csv at `runs_path`), whose outcome and metric columns must be
/// `table`'s (the rest is described again by the changed sweep).
OldColumns old_columns(const std::string& header, const SweepTable& table, const std::string& runs_path) {
  OldColumns c;
  c.names = split_csv_line(header);
  const auto position = [&](const char* name) -> std::optional<std::size_t> {
    const auto it = std::find(c.names.begin(), c.names.end(), name);
    if (it == c.names.end()) return std::nullopt;
    return static_cast<std::size_t>(it - c.names.begin());
  };
  const auto key_col = position(kRunKeyColumn);
  const auto index_col = position(kRunIndexColumn);
  const auto end_col = position(kEndReasonColumn);
  const std::size_t new_end = table.column(kEndReasonColumn);
  const auto outcome = [&](std::size_t from) {
    return table.columns().size() - new_end == c.names.size() - from;
  };
  if (!key_col || !index_col || !end_col || !outcome(*end_col) ||
      !std::equal(c.names.begin() + static_cast<std::ptrdiff_t>(*end_col), c.names.end(),
                  table.columns().begin() + static_cast<std::ptrdiff_t>(new_end))) {
    throw ConfigError(
        runs_path,
        std::string("its outcome and metric columns differ from this sweep's (made by another fsweep, "
                    "or the sweep's \"competitive\" maps changed from none to some or back?), "
                    "so its runs cannot join the changed sweep's") +
            kStartOver);
  }
  c.key = *key_col;
  c.index = *index_col;
  c.end = *end_col;
  return c;
}

/// Refuses outputs that are not extended: of an older fsweep (no map contents recorded), or of
/// other map contents.
void refuse_other_maps(const SweepPlan& plan, const std::string& dir, const nlohmann::json& old) {
  if (!old.contains("maps")) {
    throw ConfigError(
        dir, std::string("holds the results of an older fsweep: its manifest.json does not record the "
                         "maps' content, and its run keys differ from this version's") +
                 kStartOver);
  }
  if (const auto maps = changed_map_contents(old, plan); !maps.empty()) {
    std::string list;
    for (const std::string& m : maps) list += (list.empty() ? "" : "; ") + m;
    throw ConfigError(dir, "holds the results of other maps than this sweep's (" + list + ")" + kStartOver);
  }
}

/// Both files in the changed sweep's run order (progress.csv first, as always): progress rows
/// renumbered; runs.csv rows described by the changed sweep (labels, columns) with their
/// outcome. The places follow from the keys, so a kill meanwhile is repaired by the next run.
void move_rows(const SweepPlan& plan, const SweepTable& table, const OldColumns& old,
               const RunPlacement& placement, CsvJournal& runs, CsvJournal& progress) {
  const auto place_by = [&](std::size_t key_at, std::size_t index_at) {
    return [&, key_at, index_at](const std::vector<std::string>& f) -> std::optional<std::uint64_t> {
      const auto key = parse_run_key(f.at(key_at));
      const auto index = parse_run_index(f.at(index_at));
      if (!key || !index) return std::nullopt;
      return placement.new_index(*key, *index);
    };
  };
  repair_progress(progress, [&](std::uint64_t key, std::uint64_t index) {
    return placement.new_index(key, index).has_value();
  });
  const std::size_t progress_index = SweepTable::progress_column(kRunIndexColumn);
  CsvJournal::Rewrite moved_progress;
  moved_progress.place = place_by(SweepTable::progress_column(kRunKeyColumn), progress_index);
  moved_progress.fill = [&](std::uint64_t index, std::vector<std::string>& f) {
    f.at(progress_index) = std::to_string(index);
  };
  progress.rewrite_in_order(progress_index, moved_progress);
  const std::size_t new_end = table.column(kEndReasonColumn);
  CsvJournal::Rewrite moved_runs;
  moved_runs.place = place_by(old.key, old.index);
  moved_runs.fill = [&](std::uint64_t index, std::vector<std::string>& f) {
    std::vector<std::string> row;
    try {
      row = table.describe(plan, plan.run(index));
    } catch (const std::exception&) {  // a run with a column outside the header: its cells by name
      row.assign(table.columns().size(), std::string());
      for (std::size_t c = 0; c < old.end; ++c) {
        const auto it = std::find(table.columns().begin(), table.columns().end(), old.names[c]);
        if (it != table.columns().end())
          row[static_cast<std::size_t>(it - table.columns().begin())] = f.at(c);
      }
      row[table.column(kRunIndexColumn)] = std::to_string(index);
    }
    std::copy(f.begin() + static_cast<std::ptrdiff_t>(old.end), f.end(),
              row.begin() + static_cast<std::ptrdiff_t>(new_end));
    f = std::move(row);
  };
  moved_runs.header = table.header();
  runs.rewrite_in_order(table.column(kRunIndexColumn), moved_runs);
}

}  // namespace

std::uint64_t extend_outputs(const SweepPlan& plan, ShardOf shard, const SweepTable& table,
                             const std::string& dir, const nlohmann::json& old) {
  const std::string changed = "holds the outputs of another version of this sweep file (sweep_hash " +
                              old["sweep_hash"].get<std::string>() + " then, " + sweep_hash(plan.source()) +
                              " now)";
  // 1. What is not extended: exact weight searches, results of other map contents.
  if (!plan.search_units().empty() || has_search_entry(old.value("sweep", nlohmann::json())) ||
      fs::exists(dir + "/" + kSearchesFile) || fs::exists(dir + "/" + kSearchJournalFile)) {
    throw ConfigError(dir,
                      changed +
                          ", and a sweep with exact weight searches (\"search\" entries) is not extended: "
                          "its search files are of the earlier sweep's instances" +
                          kStartOver);
  }
  const std::string runs_path = dir + "/runs.csv";
  const std::string progress_path = dir + "/progress.csv";
  if (!has_rows(runs_path)) {  // nothing finished: the files start over with this sweep's columns
    fs::remove(runs_path);
    fs::remove(progress_path);
    return 0;
  }
  refuse_other_maps(plan, dir, old);
  // 2. Its columns.
  const std::string header = read_first_line(runs_path);
  const OldColumns columns = old_columns(header, table, runs_path);
  // 3. The done runs: each must have its place in the changed sweep's shard.
  CsvJournal runs(runs_path, header);
  CsvJournal progress(progress_path, SweepTable::progress_header());
  std::optional<RunPlacement> placement;
  const RowRules rules{columns.names.size(), columns.key, columns.index, columns.end, UINT64_MAX, shard};
  const Resumed resumed = repair_runs(rules, runs, [&](const DoneRuns& done) {
    placement.emplace(done);
    offer_runs(plan, shard, true, *placement);
    if (!placement->complete()) refuse_unplaced(plan, shard, old, *placement, done.size(), dir, changed);
  });
  // 4. Both files in the changed sweep's run order.
  move_rows(plan, table, columns, *placement, runs, progress);
  return resumed.done.size();
}

std::optional<std::uint64_t> parse_run_key(std::string_view s) {
  if (s.size() != 16) return std::nullopt;
  return parse_unsigned(s, 16);
}

std::optional<std::uint64_t> parse_run_index(std::string_view s) { return parse_unsigned(s); }

}  // namespace sweep
}  // namespace fsweep
