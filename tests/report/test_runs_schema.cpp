// The runs.csv schema (runs_schema.hpp): column roles, configuration keys, objectives, and
// the writer's columns read back in the roles the readers give them.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/config_error.hpp"
#include "core/config_error_message.hpp"
#include "core/csv_reader.hpp"
#include "report/runs_schema.hpp"
#include "world/map_spec.hpp"

namespace fsweep {
namespace test_runs_schema {  // not anonymous: unity builds put it beside other test files' helpers

using testing::config_error;

std::vector<std::string> names(const Columns& columns) {
  std::vector<std::string> out;
  for (const auto& [name, value] : columns) out.push_back(name);
  return out;
}

const std::vector<std::string> kHeader{
    "run_index",  "run_key",    "map_class",         "strategy_label", "map",         "map.width",
    "map.start",  "strategy",   "strategy.w1",       "planner",        "robot.dock",  "seed",
    "end_reason", "end_detail", "distance_m",        "planner_time_s", "wall_time_s", "coverage",
    "stops",      "time_s",     "optimal_distance_m"};

std::vector<std::string> names_with_role(const RunsHeader& h, ColumnRole role) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < h.names().size(); ++i) {
    if (h.role(i) == role) out.push_back(h.names()[i]);
  }
  return out;
}

TEST(RunsHeader, ClassifiesIdentityInstanceConfigOutcomeAndMetricColumns) {
  const RunsHeader h(kHeader, "runs.csv");
  using V = std::vector<std::string>;
  EXPECT_EQ(names_with_role(h, ColumnRole::Identity), (V{"run_index", "run_key"}));
  EXPECT_EQ(names_with_role(h, ColumnRole::Instance), (V{"map", "map.width", "map.start", "seed"}));
  EXPECT_EQ(names_with_role(h, ColumnRole::Config),
            (V{"map_class", "strategy_label", "strategy", "strategy.w1", "planner", "robot.dock"}));
  EXPECT_EQ(names_with_role(h, ColumnRole::Outcome), (V{"end_reason", "end_detail"}));
  EXPECT_EQ(names_with_role(h, ColumnRole::Metric), (V{"distance_m", "planner_time_s", "wall_time_s",
                                                       "coverage", "stops", "time_s", "optimal_distance_m"}));
  EXPECT_EQ(h.names_of(h.config()), names_with_role(h, ColumnRole::Config));
  EXPECT_EQ(h.names_of(h.metrics()), names_with_role(h, ColumnRole::Metric));
  EXPECT_EQ(h.run_key(), 1U);
  EXPECT_EQ(h.end_reason(), 12U);
  EXPECT_EQ(h.column("coverage"), 17);
  EXPECT_EQ(h.column("energy"), -1);
}

// Exact comparisons leave out the `*_time_s` columns; a column merely called time_s is a metric.
TEST(RunsHeader, QualityColumnsAreOutcomesAndNonTimingMetrics) {
  const RunsHeader h(kHeader, "runs.csv");
  EXPECT_EQ(h.names_of(h.quality()),
            (std::vector<std::string>{"end_reason", "end_detail", "distance_m", "coverage", "stops", "time_s",
                                      "optimal_distance_m"}));
  EXPECT_TRUE(is_effort_column("wall_time_s"));
  EXPECT_TRUE(is_effort_column("segmentation_time_s"));
  EXPECT_FALSE(is_effort_column("time_s"));
  EXPECT_FALSE(is_effort_column("wall_time_s.median"));
  EXPECT_FALSE(is_effort_column("distance_m"));
  EXPECT_TRUE(is_effort_column("planner_expansions"));
  EXPECT_FALSE(is_effort_column("planner_expansions.median"));
}

// Without end_detail the metrics start right after end_reason; a column between seed and
// end_reason is read as neither configuration nor metric.
TEST(RunsHeader, MetricsFollowEndReasonWithoutEndDetailAndColumnsAfterSeedAreNotRead) {
  const RunsHeader h({"run_key", "strategy", "seed", "note", "end_reason", "energy", "wall_time_s"}, "r.csv");
  EXPECT_EQ(h.names_of(h.config()), std::vector<std::string>{"strategy"});
  EXPECT_EQ(h.role(3), ColumnRole::Other);
  EXPECT_EQ(h.names_of(h.metrics()), (std::vector<std::string>{"energy", "wall_time_s"}));
  EXPECT_EQ(h.names_of(h.quality()), (std::vector<std::string>{"end_reason", "energy"}));
}

TEST(RunsHeader, TheCompetitiveColumnsAreMetricsButTheNoteWhichIsNotRead) {
  std::vector<std::string> header = sweep_runs_columns({"map", "strategy"}, true);
  const RunsHeader h(header, "runs.csv");
  for (const char* name : kCompetitiveColumns) {
    const int c = h.column(name);
    ASSERT_GE(c, 0) << name;
    EXPECT_EQ(h.role(static_cast<std::size_t>(c)),
              std::string_view(name) == kCompetitiveNoteColumn ? ColumnRole::Other : ColumnRole::Metric)
        << name;
  }
  EXPECT_TRUE(is_note_column("competitive_note"));
  EXPECT_FALSE(is_note_column("competitive_ratio_max"));
  EXPECT_EQ(metric_direction("competitive_ratio_max"), Direction::Minimize);
  EXPECT_EQ(metric_direction("competitive_ratio_min"), Direction::Minimize);
  EXPECT_EQ(metric_unit("optimum_lower_m"), "m");
  // Without a competitive map: none of them.
  const std::vector<std::string> plain = sweep_runs_columns({"map", "strategy"});
  EXPECT_EQ(
      std::vector<std::string>(header.begin(), header.begin() + static_cast<std::ptrdiff_t>(plain.size())),
      plain);
  EXPECT_EQ(header.size(), plain.size() + kCompetitiveColumns.size());
}

TEST(RunsHeader, MissingRequiredColumnIsNamedAtTheHeaderLine) {
  EXPECT_EQ(config_error([] {
              (void)RunsHeader({"run_key", "strategy", "end_reason"}, "a/runs.csv");
            }),
            "a/runs.csv:1: no column 'seed' in the header");
  EXPECT_EQ(config_error([] {
              (void)RunsHeader({"seed", "end_reason"}, "a/runs.csv");
            }),
            "a/runs.csv:1: no column 'run_key' in the header");
  EXPECT_EQ(config_error([] {
              (void)RunsHeader({"run_key", "seed"}, "a/runs.csv");
            }),
            "a/runs.csv:1: no column 'end_reason' in the header");
}

// The writer's columns, read back: config_columns() are configuration (the map instance and
// the seed pooled), metric_columns() are the outcome and the metrics.
TEST(RunsHeader, WriterColumnsReadBackInTheirRoles) {
  RunSpec spec;
  spec.map = std::make_shared<const WorldMap>(load_map_spec("free:w=12,h=10"));
  const std::vector<std::string> config = names(config_columns(spec));
  ASSERT_FALSE(config.empty());
  EXPECT_EQ(config.front(), kMapColumn);
  EXPECT_EQ(config.back(), kSeedColumn);
  const std::vector<std::string> metrics = names(metric_columns(RunResult{}));
  ASSERT_GE(metrics.size(), 3U);
  EXPECT_EQ(metrics[0], kEndReasonColumn);
  EXPECT_EQ(metrics[1], kEndDetailColumn);

  std::vector<std::string> config_names(config.begin(), config.end() - 1);  // without seed
  const std::vector<std::string> header = sweep_runs_columns(config_names);
  const RunsHeader h(header, "runs.csv");
  std::vector<std::string> expected_config{kMapClassColumn, kStrategyLabelColumn};
  std::copy_if(config_names.begin(), config_names.end(), std::back_inserter(expected_config),
               [](const std::string& n) {
                 return n != kMapColumn && n != kMapStartColumn && n != kMapWidthColumn &&
                        n != kMapHeightColumn;
               });
  EXPECT_EQ(h.names_of(h.config()), expected_config);
  std::vector<std::string> expected_metrics(metrics.begin() + 2, metrics.end());
  expected_metrics.insert(expected_metrics.end(), kSweepMetricColumns.begin(), kSweepMetricColumns.end());
  EXPECT_EQ(h.names_of(h.metrics()), expected_metrics);
  EXPECT_EQ(header[0], kRunIndexColumn);
  EXPECT_EQ(header[1], kRunKeyColumn);
  EXPECT_EQ(header[4 + config_names.size()], kSeedColumn);
  for (const std::string& q : h.names_of(h.quality())) EXPECT_FALSE(is_effort_column(q)) << q;
  EXPECT_NE(h.column("wall_time_s"), -1);
}

TEST(RunsSchema, ProgressColumnsAndCells) {
  EXPECT_EQ(sweep_progress_columns(), (std::vector<std::string>{"run_index", "run_key", "distance_m",
                                                                "explored_area_m2", "coverage", "energy"}));
  EXPECT_EQ(progress_cells(ProgressSample{1.5, 20.0, 0.25, std::numeric_limits<double>::infinity()}),
            "1.5,20,0.25,inf");
}

TEST(MetricValue, EmptyIsNoValueNanIsNanAnythingElseMustBeANumber) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("fsweep_runs_schema_metric_" + std::to_string(getpid()) + ".csv");
  {
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    f << "energy\n1\n2\n";
  }
  CsvReader in(path.string());
  ASSERT_TRUE(in.next());
  ASSERT_TRUE(in.next());  // the record of line 3
  EXPECT_FALSE(metric_value("", "energy", in).has_value());
  EXPECT_TRUE(std::isnan(*metric_value("nan", "energy", in)));
  EXPECT_EQ(*metric_value("inf", "energy", in), std::numeric_limits<double>::infinity());
  EXPECT_EQ(*metric_value("-2.5e3", "energy", in), -2500.0);
  EXPECT_EQ(config_error([&] { (void)metric_value("12 J", "energy", in); }),
            path.string() + ":3: column 'energy': '12 J' is not a number");
  std::filesystem::remove(path);
}

TEST(SuccessfulEnd, CompleteAndTargetReachedOnly) {
  EXPECT_TRUE(successful_end("complete"));
  EXPECT_TRUE(successful_end("target_reached"));
  for (const char* other : {"range_limited", "stuck", "error", "target_unreachable", ""})
    EXPECT_FALSE(successful_end(other)) << other;
}

TEST(ConfigKey, EachValueIsFollowedByTheSeparator) {
  const std::vector<std::string> fields{"a", "bc", "", "d"};
  EXPECT_EQ(config_key(fields, {0, 1}),
            "a\x1f"
            "bc\x1f");
  EXPECT_EQ(config_key(fields, {2, 3}),
            "\x1f"
            "d\x1f");
  EXPECT_EQ(config_key(fields, {}), "");
  // A column a file does not have (-1) is an empty value.
  EXPECT_EQ(config_key(fields, {0, -1, 3}), config_key({"a", "", "d"}, {0, 1, 2}));
}

TEST(ConfigKey, TellsApartValuesThatConcatenateAlike) {
  EXPECT_NE(config_key({"a", "bc"}, {0, 1}), config_key({"ab", "c"}, {0, 1}));
  EXPECT_NE(config_key({"", "x"}, {0, 1}), config_key({"x", ""}, {0, 1}));
}

TEST(ConfigKey, SplitGivesBackTheValues) {
  const std::vector<std::string> values{"free", "", "energy_aware", "1;2", "a,b"};
  EXPECT_EQ(split_config_key(config_key(values, {0, 1, 2, 3, 4})), values);
  EXPECT_TRUE(split_config_key("").empty());
}

TEST(ConfigKey, RunsHeaderKeysOverItsConfigColumns) {
  const RunsHeader h(
      {"run_index", "run_key", "map", "strategy", "strategy.w1", "seed", "end_reason", "energy"}, "runs.csv");
  const std::vector<std::string> a{"0", "00a0", "free:seed=1", "energy_aware", "10", "1", "complete", "5"};
  const std::vector<std::string> b{"1", "00b0", "free:seed=2", "energy_aware", "10", "2", "stuck", "7"};
  EXPECT_EQ(h.config_key(a), config_key(a, {3, 4}));
  EXPECT_EQ(h.config_key(a), h.config_key(b));  // another map instance and seed: same configuration
}

TEST(Objectives, DefaultFirstEachWithDirectionAndMetricColumn) {
  EXPECT_EQ(kObjectives[0].name, "distance_to_final_coverage_m");
  EXPECT_EQ(objective_names(), (std::vector<std::string>{"distance_to_final_coverage_m", "area_per_metre",
                                                         "energy", "distance_to_coverage_target_m"}));
  // Only the coverage target's distance is missing for some runs (those that never reach it).
  for (const Objective& o : kObjectives)
    EXPECT_EQ(o.missing_is_worst, o.name == "distance_to_coverage_target_m") << o.name;
  const Objective* area = find_objective("area_per_metre");
  ASSERT_NE(area, nullptr);
  EXPECT_EQ(area->direction, Direction::Maximize);
  EXPECT_EQ(area->column, "area_per_metre");
  EXPECT_EQ(find_objective("energy")->direction, Direction::Minimize);
  EXPECT_EQ(&require_objective("energy", "--objective"), find_objective("energy"));
  // Each objective ranks by a metric the writer produces.
  const std::vector<std::string> metrics = names(metric_columns(RunResult{}));
  for (const Objective& o : kObjectives)
    EXPECT_NE(std::find(metrics.begin(), metrics.end(), o.column), metrics.end()) << o.name;
}

TEST(Objectives, UnknownNameListsTheKnownOnes) {
  EXPECT_EQ(find_objective("speed"), nullptr);
  EXPECT_EQ(find_objective(""), nullptr);
  EXPECT_EQ(config_error([] { (void)require_objective("speed", "--objective"); }),
            "--objective: unknown objective 'speed'; allowed: distance_to_final_coverage_m, area_per_metre, "
            "energy, distance_to_coverage_target_m");
}

}  // namespace test_runs_schema
}  // namespace fsweep
