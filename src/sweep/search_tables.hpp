#pragma once
/// @file search_tables.hpp
/// The rows of one exact weight search's CSV files (weight_search_runner.hpp lists the files and
/// docs/weight-search.md their columns) from its behaviours, and the writing of the files of a
/// sweep's searches. The search itself, its journal and the merge of shards are
/// weight_search_runner.cpp's.

#include <array>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "report/runs_schema.hpp"
#include "sweep/sweep_plan.hpp"
#include "weightsearch/exact_search.hpp"
#include "weightsearch/weight_grid.hpp"

namespace fsweep {
inline namespace sweep {

/// One behaviour, formatted: its metric cells per instance and the numbers they hold.
struct FoundBehaviour {
  Behaviour behaviour;
  /// Per instance, the metric columns (runs.csv's, plus optimal_distance_m and
  /// competitive_ratio; effort metrics empty).
  std::vector<Columns> cells;
  /// Per instance and metric column, the value (NaN: none); filled by SearchTables::format().
  std::vector<std::vector<double>> values;
  double objective = std::numeric_limits<double>::quiet_NaN();
  /// Which of the search's `rank` vectors it holds (positions in WeightSearch::rank), noted
  /// when it was admitted (SearchTables::admit()), so that its region need not be kept.
  std::vector<std::size_t> ranked;
};

/// How many distinct outcomes `found` holds: behaviours whose metric cells (end reason and detail,
/// every metric but the effort ones, on every instance) are all equal count once. Different
/// decision sequences can end in the same outcome (the same distance, coverage and counts).
[[nodiscard]] std::size_t distinct_outcomes(const std::vector<FoundBehaviour>& found);

/// Better objective first; no value last.
[[nodiscard]] bool better_objective(double a, double b, Direction direction);

/// A planner as tables show it: its name, and its parameters when given.
[[nodiscard]] std::string planner_label(const SweepPlanner& p);

/// Everything one search writes, as text rows (each with its newline), and its searches.json record.
// NOLINTNEXTLINE(bugprone-exception-escape): false positive inside nlohmann::json's noexcept move
struct SearchRows {
  std::string behaviours;
  std::string summary;
  std::string best;
  std::string ranks;
  std::string heatmaps;
  std::string vectors;
  nlohmann::json record;
};

/// Heat maps over weight pairs, filled one behaviour at a time (SearchTables::admit()): per
/// pair of weights (a, b) and pair of their values, the best objective among the behaviours
/// with a vector there, and of the behaviours with that objective the smallest representative.
/// Behaviour ids follow the representatives, so that is the smallest id: what a walk over
/// every behaviour in id order, keeping the first of the best, gives.
class HeatMaps {
 public:
  using Point = std::array<int, WeightGrid::kMaxWeights>;
  /// `wanted`: false for a search without heat maps (mode best), which then holds none.
  HeatMaps(const WeightGrid& grid, Direction direction, bool wanted);

  /// Adds a behaviour: its region, objective and representative.
  void add(const WeightRegion& region, double objective, const Point& representative);

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

/// The tables of search `id` (unit `unit` of `plan`, objective `objective`): its weight grid,
/// mode all's running results (heat maps, the `rank` vectors' owners) and the files' rows.
class SearchTables {
 public:
  SearchTables(const SweepPlan& plan, const SearchUnit& unit, std::size_t id, const Objective& objective);
  // Its heat maps refer to its grid.
  SearchTables(const SearchTables&) = delete;
  SearchTables& operator=(const SearchTables&) = delete;

  [[nodiscard]] const WeightGrid& grid() const { return grid_; }

  /// Takes a behaviour of the whole grid (one search's, or one the shards' parts make up) into
  /// mode all's running results: the rank vectors it holds and its heat-map cells. Its region is
  /// then dropped unless vectors.csv needs it: the full [0, 250]^4's behaviours would hold tens
  /// of gigabytes of regions, these results a few megabytes.
  void admit(FoundBehaviour& f);

  /// The rows of the files for `found`, every behaviour of the whole grid that the files list
  /// (mode best: the optimal ones), each admitted: `found` is put in the order of the
  /// representatives (the behaviour ids) and its values are filled. `specs`: the instances.
  void format(std::vector<FoundBehaviour>& found, const std::vector<RunSpec>& specs, SearchRows& rows) const;

  /// Header lines (no newline) of the files (report/search_schema.hpp).
  static std::string behaviours_header(const WeightSearch& s);
  static std::string summary_header();
  static std::string best_header(const WeightSearch& s);
  static std::string ranks_header(const WeightSearch& s);
  static std::string heatmaps_header();
  static std::string vectors_header(const WeightSearch& s);

 private:
  [[nodiscard]] std::string value_at(int k, int index) const;
  void write_behaviours(const std::vector<FoundBehaviour>& found, const std::vector<RunSpec>& specs,
                        SearchRows& rows) const;
  void write_summary(const std::vector<FoundBehaviour>& found, std::size_t instances, SearchRows& rows) const;
  /// Vectors strictly better than `objective` and those equal to it.
  [[nodiscard]] std::pair<std::uint64_t, std::uint64_t> standing(const std::vector<FoundBehaviour>& found,
                                                                 double objective) const;
  void write_best_and_ranks(const std::vector<FoundBehaviour>& found, SearchRows& rows) const;
  void write_heatmaps(const std::vector<FoundBehaviour>& found, SearchRows& rows) const;
  void write_vectors(const std::vector<FoundBehaviour>& found, SearchRows& rows) const;

  const SweepPlan& plan_;
  const SearchUnit& unit_;
  std::string id_;
  const WeightSearch& search_;
  const Objective& objective_;
  WeightGrid grid_;
  /// Mode all: the heat maps and the positions in the grid of the `rank` vectors.
  HeatMaps heat_;
  std::vector<HeatMaps::Point> rank_points_;
};

struct SearchRunReport;

/// Writes the files of the searches `units` of `plan` from their rows (one per unit) into
/// `out_dir`, searches.json last, and counts them in `report`.
void write_search_files(const SweepPlan& plan, const std::vector<SearchUnit>& units,
                        std::vector<SearchRows> rows, const std::string& out_dir, SearchRunReport& report);

}  // namespace sweep
}  // namespace fsweep
