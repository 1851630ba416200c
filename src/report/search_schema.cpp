#include "report/search_schema.hpp"

#include <algorithm>

#include "core/statistics.hpp"
#include "report/runs_schema.hpp"
#include "sim/run_result.hpp"

namespace fsweep {
inline namespace report {

namespace {
constexpr std::string_view kCertificatePrefix = "search_certificate_";
constexpr std::string_view kCertificateSuffix = ".jsonl";
constexpr std::string_view kStatusPrefix = "search_status_";
constexpr std::string_view kStatusSuffix = ".json";
}  // namespace

std::string search_certificate_file(std::size_t id) {
  return std::string(kCertificatePrefix) + std::to_string(id) + std::string(kCertificateSuffix);
}

bool is_search_certificate_file(std::string_view name) {
  return name.starts_with(kCertificatePrefix) && name.ends_with(kCertificateSuffix);
}

std::string search_status_file(std::size_t id) {
  return std::string(kStatusPrefix) + std::to_string(id) + std::string(kStatusSuffix);
}

bool is_search_status_file(std::string_view name) {
  return name.starts_with(kStatusPrefix) && name.ends_with(kStatusSuffix);
}

std::vector<std::string> search_anytime_columns() {
  return {kSearchIdColumn, "elapsed_s", "status", "resolved_vectors", kVectorsColumn, "open_branches",
          "best",          "bound",     "gap",    "relative_gap"};
}

std::vector<std::string> behaviours_columns(std::span<const std::string> weights) {
  std::vector<std::string> h{kSearchIdColumn, kBehaviourIdColumn, kVectorsColumn};
  for (const auto& w : weights) h.push_back(w);
  for (const auto& w : weights) {
    h.push_back(w + ".min");
    h.push_back(w + ".max");
  }
  for (const char* c : {kObjectiveColumn, kInstanceColumn, kMapColumn, kSeedColumn}) h.emplace_back(c);
  for (const auto& [name, value] : metric_columns(RunResult{})) h.push_back(name);
  for (const char* c : kSweepMetricColumns) h.emplace_back(c);
  return h;
}

std::vector<std::string> search_summary_columns() {
  std::vector<std::string> h{kSearchIdColumn, "strategy_label", "map_class",    "planner",
                             "robot",         "instances",      kVectorsColumn, "behaviours"};
  for (int r = static_cast<int>(EndReason::Complete); r <= static_cast<int>(EndReason::Error); ++r) {
    h.push_back("end." + std::string(to_string(static_cast<EndReason>(r))));
  }
  Columns names = metric_columns(RunResult{});
  for (const char* c : kSweepMetricColumns) names.emplace_back(c, "");
  for (const auto& [name, cell] : names) {
    if (name == kEndReasonColumn || name == kEndDetailColumn || is_effort_column(name)) continue;
    for (const std::string_view s : kStatisticNames) h.push_back(name + "." + std::string(s));
  }
  return h;
}

std::vector<std::string> search_best_columns(std::span<const std::string> weights) {
  std::vector<std::string> h{kSearchIdColumn, kRankColumn,      kBehaviourIdColumn,
                             kVectorsColumn,  "vectors_better", kObjectiveColumn};
  for (const auto& w : weights) h.push_back(w);
  return h;
}

std::vector<std::string> search_best_weights(const std::vector<std::string>& header) {
  const auto objective = std::find(header.begin(), header.end(), std::string(kObjectiveColumn));
  return {objective == header.end() ? header.end() : objective + 1, header.end()};
}

std::vector<std::string> search_ranks_columns(std::span<const std::string> weights) {
  std::vector<std::string> h{kSearchIdColumn};
  for (const auto& w : weights) h.push_back(w);
  for (const char* c :
       {kBehaviourIdColumn, kObjectiveColumn, kRankColumn, "vectors_better", "vectors_tied", "percentile"}) {
    h.emplace_back(c);
  }
  return h;
}

std::vector<std::string> search_heatmaps_columns() {
  return {kSearchIdColumn, "weight_a",       "weight_b",        "value_a",
          "value_b",       "best_objective", kBehaviourIdColumn};
}

std::vector<std::string> vectors_columns(std::span<const std::string> weights) {
  std::vector<std::string> h{kSearchIdColumn};
  for (const auto& w : weights) h.push_back(w);
  h.emplace_back(kBehaviourIdColumn);
  return h;
}

}  // namespace report
}  // namespace fsweep
