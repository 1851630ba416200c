#pragma once
/// @file sweep_plan.hpp
/// A sweep file, validated and expanded lazily into runs (docs/dev/architecture.md, "Sweeps, keys, shards and
/// the weight search").
///
/// # Format (schema_version 1)
///
/// Top-level keys (any other key is an error):
/// - `schema_version` (required): must be kSweepSchemaVersion.
/// - `name` (required): [A-Za-z0-9_.-]+, not "." or ".." (it names the output folder).
/// - `description`: free text.
/// - `maps` (required, non-empty list). Each item is a map SPEC string (map_spec.hpp:
///   "rooms:w=120,h=80,seed=4", "maps/x.map:res=0.5"), or an object: either a load_map_json
///   object ({"generator": "rooms", "w": 120} or {"file": "maps/x.map", "res": 0.5}) or
///   {"spec": "SPEC string"}, plus optional `label` (text for tables) and, for generators,
///   `seeds`: a sweep value (below) of generator seeds; the item then expands into one map per
///   seed, in the order of the values (a `seed` key next to `seeds` is an error). Relative
///   paths (map files, a dataset's folder and id list) are relative to the sweep file's folder;
///   one found only under the working directory (where sweeps used to name them from) is read
///   from there with a warning (path_warnings()). They are kept as written in run keys, labels
///   and runs.csv, so none of these depends on where the files lie. Every map is loaded during
///   validation and kept in memory for the whole sweep.
/// - `strategies` (required, non-empty list of {"name", "label"?, "params"?, "zip"?,
///   "vectors"?}): `params` maps each strategy parameter to a sweep value. `zip` is a list of
///   groups (lists of parameter names) whose values vary together: the lists of one group must
///   have equal lengths (values may repeat, tuples may not), a parameter may be in one group
///   only. `vectors` lists whole tuples, one more zipped group (docs/sweeps.md, "Product").
/// - `planners`: list of {"type": name, "params": {...}} or plain name strings; default
///   [{"type": "astar"}]. Planner parameters are not swept (list several planners instead).
/// - `robot`: the robot_params_from_json object (run_spec.hpp), where any leaf may be a sweep
///   value. `dock` and `energy/per_turn` take arrays as values: there a list of arrays is a
///   sweep ("dock": [[3, 4], [10, 2]]) and a plain array is one value ("dock": [3, 4]).
///   A dock must be a free cell of every map.
/// - `sim`: the sim_params_from_json object (not swept). `progress_step_m` may also be given
///   at the top level (as the issue names it), but not in both places.
/// - `repetitions`: integer from 1 to kMaxRepetitions, default 1. `seed`: unsigned integer, default 0.
/// - `output`: {"dir": path (default "results/<name>"; relative to the working directory),
///   "objective": "distance_to_final_coverage_m" (default) | "area_per_metre" | "energy"}.
/// - `competitive`: boolean, default false: whether the maps are competitive (SweepMap::competitive);
///   a map item (object) may give its own `competitive`, which wins. Not part of run keys.
///
/// Command-line overrides ("robot.battery=800", apply_sweep_overrides() in sweep_json_reader.hpp)
/// change the parsed JSON before validation; source() and the manifest's sweep and hash are of
/// the sweep so changed.
///
/// Sweep values (strategy parameters, robot leaves, map seeds), see expand_values():
/// - a scalar or an object without a "range" key: one value (where the robot takes an object,
///   `sensor` and `energy`, an object is that object, so a "range" key in it is an unknown key);
/// - a list: each element is one value, in order (so an array-valued strategy parameter is
///   written as a list of arrays, e.g. [[3, 4]] for the single value [3, 4]);
/// - {"range": [lo, hi], "step": s}: lo, lo + s, ..., hi inclusive. `step` is required and
///   must be > 0; lo <= hi. If lo, hi and s are integers the values are integers. Otherwise
///   value i is lo + i*s rounded to the decimals of lo, hi and s (so 0.1 steps give 0.3, not
///   0.30000000000000004); hi is included when it is within 1e-9 steps of a grid point.
/// - at most kMaxAxisValues values per axis; duplicate values in one axis are errors (they
///   would give runs with equal run keys), but for zipped axes, where only repeated tuples are
///   errors. Nothing is clamped or rounded silently.
///
/// # Validation
/// Every problem is collected and thrown as one ConfigError whose message lists them, one per
/// line, as "<file>: <JSON path>: <what is wrong, the bad value, what is allowed>". Strategy
/// parameters are not validated combination by combination (a weight search has 251^4 of
/// them): each axis value is checked by the strategy's own parser alone (the other parameters
/// at their defaults) and with the first value of every other axis, and is bad when both
/// fail; then each zip combination and the first combination are checked whole. One problem
/// is reported per axis (its first bad value and how many more fail). Robot leaves are checked
/// the same way, then every robot variant (they are materialised, at most kMaxRobotVariants).
/// Checked against every map: a given dock is a free cell, the sensor range is at least one
/// diagonal cell. Repeated maps, planners, robot variants or list values are errors (their
/// runs would have equal run keys), and so is the same configuration reached from two strategy
/// entries (check_entry_overlaps(), entry_overlap.hpp). A sweep of more than 2^64 runs is an error.

/// # Run order
/// The order of rows in every output: maps (slowest), then strategy configurations (entries
/// in file order; inside an entry the parameter groups in mixed-radix order, LAST group
/// fastest), then planners, then robot variants, then repetitions (fastest):
///   index = (((map * S + strategy) * P + planner) * R + robot) * repetitions + repetition.
/// Parameter groups of an entry: every parameter outside a zip group is a group of its own;
/// groups are ordered by their alphabetically smallest parameter (JSON objects are read with
/// sorted keys, so the file's key order cannot be kept). Robot axes: the swept leaves in
/// depth-first sorted-key order of their JSON paths (e.g. /battery before /sensor/range_m),
/// last fastest. Run i is decoded from i, so a sweep of 10^9 runs costs no memory.
///
/// # Seeds and keys
/// Run seed = derive_seed(sweep seed, "repetition/<r>"), the same for every configuration at
/// repetition r (common random numbers: configurations are compared on the same draws). Map
/// generator seeds are map parameters, expanded by a map's "seeds".
/// run_key = FNV-1a 64 of the dump() of {"map": canonical spec, "strategy", "strategy_params":
/// recorded_strategy_params (the resolved params, plus "heuristics" when the entry gives them),
/// "planner", "planner_params" as written (null when absent or empty), "robot":
/// to_json(RobotParams) with the dock resolved to the map's start, "sim", "seed"}. The map's
/// canonical spec is its JSON object form (a SPEC string is parsed into the same object as the
/// equivalent JSON item; integral floats become integers; file paths are lexically normalised),
/// without `label`/`seeds`. "map_content" is the loaded map's content_hash() (world_map.hpp), so
/// an edited map file changes its runs' keys. Same configuration, map content and seed: same
/// key, in any sweep.

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "report/runs_schema.hpp"
#include "sim/run_spec.hpp"
#include "sweep/sweep_json_reader.hpp"
#include "weightsearch/search_order.hpp"

namespace fsweep {
inline namespace sweep {

/// The most repetitions a sweep may ask for: the repetition index is an `int`
/// (RunCoordinates::repetition), so 2^31 - 1.
inline constexpr std::int64_t kMaxRepetitions = std::numeric_limits<int>::max();

/// The JSON schema version this build reads.
inline constexpr int kSweepSchemaVersion = 1;

/// Most values one axis (one list or range) may have.
inline constexpr std::uint64_t kMaxAxisValues = 1'000'000;

/// Most robot variants a sweep may have (they are materialised).
inline constexpr std::uint64_t kMaxRobotVariants = 1'000'000;

/// Expands one sweep value (format above): a scalar or non-range object (one value), a list
/// (its elements), or {"range": [lo, hi], "step": s}. Appends problems ("<where>: message"
/// with the bad value and what is allowed) to `problems` and returns no values for a bad one.
/// A list's repeated values are a problem unless `repeats_allowed` (a zipped parameter: its
/// tuples must differ, not its values).
[[nodiscard]] std::vector<nlohmann::json> expand_values(const nlohmann::json& v, const std::string& where,
                                                        std::vector<std::string>& problems,
                                                        bool repeats_allowed = false);

/// One map of the sweep after expanding its "seeds"; loaded once at validation.
// NOLINTNEXTLINE(bugprone-exception-escape): false positive inside nlohmann::json's noexcept move
struct SweepMap {
  /// Short label for tables: the item's `label` (plus " seed=N" when seeds expand), else the
  /// spec string or the object written as a spec string.
  std::string label;
  /// The map class: the item's `label`, else its spec without the generator seed. All maps a
  /// `seeds` list expands into share it; summaries pool runs over the maps of one class (so
  /// map seeds act as repetitions), and weights can be ranked per class. Items given the same
  /// label form one class.
  std::string map_class;
  /// Canonical JSON object of the source (what the run key hashes; see above).
  nlohmann::json spec;
  std::shared_ptr<const WorldMap> map;
  /// content_hash() of `map` as 16 hex digits: run keys cover it, so an edited map file changes
  /// its runs' keys; manifest.json records it per map ("maps") and a resume refuses a change.
  std::string content_hash;
  /// Its runs get the offline optimum's columns (runs_schema.hpp's kCompetitiveColumns,
  /// optimum_table.hpp): the sweep's `competitive`, or its item's.
  bool competitive = false;
  /// True for the `free` generator (the star-pattern optimum of docs/dev/architecture.md, "Sweeps, keys,
  /// shards and the weight search" applies).
  bool free_space = false;
  /// `start: "random"`: the cells each run draws its start from (draw_region_cell() with the run
  /// seed), per motion rule: [0] without corner cutting, [1] with (largest_free_region(),
  /// world_map.hpp). Null: every run starts at map->start.
  std::shared_ptr<const std::array<Grid<std::uint8_t>, 2>> start_regions;
};

/// A plan of a dataset item that did not load and was skipped (`"on_bad_map": "skip"`).
struct SkippedMap {
  std::string where;  ///< JSON path of the dataset item
  std::string file;   ///< the plan's file
  std::string reason;
};

/// The exact weight search of a strategy entry ("search" in the file; format above): every
/// weight vector of a box, searched by decision sharing (exact_search.hpp).
struct WeightSearch {
  enum class Mode { All, Best };
  Mode mode = Mode::All;
  /// Mode best: the order branches are explored in (SearchOrder, exact_search.hpp) and, for
  /// SearchOrder::Bound, the most branches kept waiting.
  SearchOrder order = SearchOrder::Depth;
  std::size_t max_open = kDefaultMaxOpenBranches;
  /// Mode best: weight vectors run alone first, the best their first incumbent.
  std::size_t probes = kDefaultProbes;
  /// Also write vectors.csv (boxes of at most kMaxListedVectors vectors).
  bool write_vectors = false;
  /// The strategy's weight parameters (LinearScoredStrategy::weight_names()), in its order.
  std::vector<std::string> weights;
  /// Per weight, its values, ascending (integers unless the file gives others).
  std::vector<std::vector<double>> values;
  /// Weight vectors (one value per weight, each a value of the box) whose exact rank is reported.
  std::vector<std::vector<double>> rank;
  /// Vectors in the box (the product of the value counts).
  [[nodiscard]] std::uint64_t vectors() const;
};

/// Most vectors a search's vectors.csv may list.
inline constexpr std::uint64_t kMaxListedVectors = 10'000'000;

/// A strategy entry: a name and parameter axes. Axes in a "zip" group vary together.
struct StrategyEntry {
  std::string name;
  std::string label;  ///< "label" in the file, else the name
  struct Group {
    std::vector<std::string> names;                   ///< parameter names of the group
    std::vector<std::vector<nlohmann::json>> combos;  ///< combos[k][i]: value of names[i]
  };
  /// Ordered by each group's alphabetically smallest name; a group's names in zip order. In a
  /// search entry, the weights are not among them (they are the search's box) and every other
  /// group has one value.
  std::vector<Group> groups;
  /// The entry's exact weight search, if it has one: then it has no runs of its own.
  std::optional<WeightSearch> search;
  /// Number of parameter combinations (product of the groups' sizes; 1 without params), each a
  /// configuration of the sweep's runs; 0 for a search entry.
  [[nodiscard]] std::uint64_t count() const;
  /// Parameters of combination k (0 <= k < count()), last group fastest, as the strategy's
  /// params object; null when the entry has no parameters (the strategy's defaults).
  [[nodiscard]] nlohmann::json params_at(std::uint64_t k) const;
};

/// One planner of the sweep: a registry name and its parameters.
// NOLINTNEXTLINE(bugprone-exception-escape): false positive inside nlohmann::json's noexcept move
struct SweepPlanner {
  std::string name;
  nlohmann::json params;  ///< null: defaults
};

/// One robot variant.
struct RobotVariant {
  RobotParams params;
  /// The variant as robot JSON (the file's robot object with every swept leaf set).
  nlohmann::json json;
  /// The swept leaves of this variant, "path=value" separated by spaces ("-" when nothing is
  /// swept), e.g. "battery=400 sensor.range_m=6".
  std::string label;
};

/// Where a run sits on every axis.
struct RunCoordinates {
  std::uint64_t index = 0;
  std::size_t map = 0;
  std::size_t strategy_entry = 0;
  std::uint64_t strategy_combo = 0;
  std::size_t planner = 0;
  std::size_t robot = 0;
  int repetition = 0;
};

/// One exact weight search of a sweep: a search entry on one map class with one planner and
/// one robot variant. Its instances, searched jointly, are the class's maps times the
/// repetitions (map-major).
struct SearchUnit {
  std::size_t entry = 0;
  std::string map_class;
  /// The class's maps, in file order.
  std::vector<std::size_t> maps;
  std::size_t planner = 0;
  std::size_t robot = 0;
};

/// One run of a sweep, resolved once: its place on every axis, its RunSpec (plugins
/// configured, typed), the canonical JSON its key hashes and the key. The run key, the runs.csv
/// columns (config_columns(spec)) and the Simulation all read this one value.
struct SweepRun {
  RunCoordinates at;
  RunSpec spec;
  nlohmann::json key_json;
  std::string key;
};

/// A validated sweep. Cheap to query from many threads (all methods are const and pure).
class SweepPlan {
 public:
  /// Parses and validates `sweep` (read from `file`: used in messages, and its folder is where
  /// relative paths are found; "" or a bare name: the working directory). Every problem is
  /// collected and thrown at once as one ConfigError (where() = file) whose message lists
  /// them, one per line, "<file>: <JSON path>: <message>". Loads every map.
  static SweepPlan from_json(const nlohmann::json& sweep, const std::string& file);
  /// Reads the file, applies the command-line `overrides` ("PATH=VALUE", in order;
  /// apply_sweep_overrides(), which throws for one that cannot be applied) and validates the
  /// result as from_json does; a problem at or under an override's path is reported as
  /// "<file>: override '<text>': <JSON path>: <message>". A missing file names the file; bad
  /// JSON, a number beyond a double and nesting deeper than kMaxSweepNesting name the file,
  /// line and column (parse_sweep_json()); duplicate keys in one object are problems (JSON
  /// would keep only the last).
  static SweepPlan from_file(const std::string& path, const std::vector<std::string>& overrides = {});

  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] const std::string& description() const { return description_; }
  /// The sweep file's JSON as read, with the overrides applied (paths as written).
  [[nodiscard]] const nlohmann::json& source() const { return source_; }
  /// The command-line overrides applied to it, as given.
  [[nodiscard]] const std::vector<std::string>& overrides() const { return overrides_; }
  /// One warning per relative path found only under the working directory, not beside the sweep
  /// file (sweep_table.hpp's sweep_warnings() lists them first).
  [[nodiscard]] const std::vector<std::string>& path_warnings() const { return path_warnings_; }
  /// Output directory: "output": {"dir": ...} or results/<name>.
  [[nodiscard]] const std::string& output_dir() const { return output_dir_; }
  /// Ranking objective for best.csv: a name of runs_schema.hpp's kObjectives (default the first).
  [[nodiscard]] const std::string& objective() const { return objective_; }
  [[nodiscard]] int repetitions() const { return repetitions_; }
  [[nodiscard]] std::uint64_t seed() const { return seed_; }

  /// configuration_count() * repetitions() (validation guarantees it fits in 64 bits).
  [[nodiscard]] std::uint64_t run_count() const;
  /// Runs per repetition (= distinct configurations): maps x strategy configurations x
  /// planners x robot variants.
  [[nodiscard]] std::uint64_t configuration_count() const;
  /// Strategy configurations over all entries.
  [[nodiscard]] std::uint64_t strategy_configuration_count() const { return strategy_offsets_.back(); }
  /// The strategy configurations of the entries before entry `e` (0 <= e <= entries).
  [[nodiscard]] std::uint64_t strategy_offset(std::size_t e) const { return strategy_offsets_.at(e); }
  /// Mixed-radix decode of `index` (< run_count(); throws std::out_of_range otherwise).
  [[nodiscard]] RunCoordinates coordinates(std::uint64_t index) const;
  /// Run `index` resolved once (see SweepRun).
  [[nodiscard]] SweepRun run(std::uint64_t index) const;
  /// The fully resolved run (map shared, not copied).
  [[nodiscard]] RunSpec run_spec(std::uint64_t index) const;
  /// 16 lowercase hex digits: FNV-1a 64 of the canonical JSON (see above). Stable across
  /// builds and platforms.
  [[nodiscard]] std::string run_key(std::uint64_t index) const;
  /// The canonical JSON the run key hashes.
  [[nodiscard]] nlohmann::json run_key_json(std::uint64_t index) const;
  /// The exact weight searches, in order: search entries in file order, then map classes by
  /// first appearance, planners, robot variants (last fastest).
  [[nodiscard]] std::vector<SearchUnit> search_units() const;
  /// Instance `instance` of `unit` (< maps x repetitions; map-major): the RunSpec a run of the
  /// entry on that map and repetition would have, its strategy with its default weights.
  [[nodiscard]] RunSpec search_instance(const SearchUnit& unit, std::size_t instance) const;
  /// The canonical JSON of that instance (as run keys hash it, with the search's box in place
  /// of the weights): every resolved parameter.
  [[nodiscard]] nlohmann::json search_instance_json(const SearchUnit& unit, std::size_t instance) const;
  /// Axis sizes, for `fsweep expand`: maps, strategy configurations, planners, robots, reps.
  [[nodiscard]] std::vector<std::pair<std::string, std::uint64_t>> axes() const;

  [[nodiscard]] const std::vector<SweepMap>& maps() const { return maps_; }
  /// True when some map is competitive (SweepMap::competitive): runs.csv has kCompetitiveColumns.
  [[nodiscard]] bool competitive() const;
  /// Plans of dataset items skipped because they failed to load (manifest.json, the CLI's warnings).
  [[nodiscard]] const std::vector<SkippedMap>& skipped_maps() const { return skipped_maps_; }
  [[nodiscard]] const std::vector<StrategyEntry>& strategies() const { return strategies_; }
  [[nodiscard]] const std::vector<SweepPlanner>& planners() const { return planners_; }
  [[nodiscard]] const std::vector<RobotVariant>& robots() const { return robots_; }
  [[nodiscard]] const SimParams& sim() const { return sim_; }

 private:
  static SweepPlan build(const nlohmann::json& sweep, const std::string& file,
                         std::vector<std::string> problems, const std::vector<SweepOverride>& overrides);
  // build()'s steps; each adds what it finds wrong to `problems`.
  /// schema_version, name, description, repetitions, seed; returns "competitive" (false when
  /// not given or wrong).
  bool read_settings(const nlohmann::json& sweep, std::vector<std::string>& problems);
  void read_output(const nlohmann::json& output, std::vector<std::string>& problems);
  /// "baseline": a strategy entry's label (for a search entry "<label>@...").
  void check_baseline(const nlohmann::json& baseline, std::vector<std::string>& problems) const;
  /// The robots against the maps: the dock is a free cell, the sensor sees the 8 neighbours and
  /// its range in cells is one the sensor supports.
  void check_robots_on_maps(std::vector<std::string>& problems) const;
  /// The strategy configurations' prefix sums, and that they and the runs fit in 64 bits.
  void count_runs(std::vector<std::string>& problems);
  [[nodiscard]] RunSpec spec_at(const RunCoordinates& c) const;
  [[nodiscard]] nlohmann::json key_json_of(const RunCoordinates& c, const RunSpec& spec) const;

  std::string name_;
  std::string description_;
  nlohmann::json source_;
  std::vector<std::string> overrides_;
  std::vector<std::string> path_warnings_;
  std::string output_dir_;
  std::string objective_{kObjectives[0].name};
  int repetitions_ = 1;
  std::uint64_t seed_ = 0;
  std::vector<SweepMap> maps_;
  std::vector<SkippedMap> skipped_maps_;
  std::vector<StrategyEntry> strategies_;
  std::vector<std::uint64_t> strategy_offsets_{0};  ///< prefix sums of entries' counts
  std::vector<SweepPlanner> planners_;
  std::vector<RobotVariant> robots_;
  SimParams sim_;
};

}  // namespace sweep
}  // namespace fsweep
