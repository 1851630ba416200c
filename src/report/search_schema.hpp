#pragma once
/// @file search_schema.hpp
/// The files of a sweep's exact weight searches (docs/weight-search.md, "Output files"): their
/// names and columns, the one place that says them for the writer (sweep/weight_search_runner.cpp)
/// and the readers (result_dir.cpp, paired.cpp), as runs_schema.hpp does for runs.csv.
///
/// Every file has a row per search and behaviour (or vector, or heat-map cell), its search by
/// kSearchIdColumn, the position of its search in searches.json. Weight columns carry the
/// strategy's weight names (w1, w2, ...) and come where the column lists below say.

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fsweep {
inline namespace report {

// ---- File names.
inline constexpr char kSearchesFile[] = "searches.json";  ///< written last: the files are complete
inline constexpr char kBehavioursFile[] = "behaviours.csv";
inline constexpr char kSearchBestFile[] = "search_best.csv";
inline constexpr char kSearchSummaryFile[] = "search_summary.csv";
inline constexpr char kSearchRanksFile[] = "search_ranks.csv";
inline constexpr char kSearchHeatmapsFile[] = "search_heatmaps.csv";
inline constexpr char kVectorsFile[] = "vectors.csv";
inline constexpr char kSearchJournalFile[] = "search_journal.jsonl";
/// Mode best's finished probes, taken up on resume (weightsearch/search_probes.hpp).
inline constexpr char kSearchProbesFile[] = "search_probes.jsonl";
/// Mode best's certificate of search `id` (docs/dev/weight-search-design.md, "The certificate").
[[nodiscard]] std::string search_certificate_file(std::size_t id);
/// Whether a file name is a certificate's (`fsweep run --fresh` deletes them).
[[nodiscard]] bool is_search_certificate_file(std::string_view name);
/// The curve of mode best's best objective and bound over time, every search's rows
/// (sweep/search_anytime.hpp).
inline constexpr char kSearchAnytimeFile[] = "search_anytime.csv";
/// Mode best's latest state of search `id`: best, bound, gap (sweep/search_anytime.hpp).
[[nodiscard]] std::string search_status_file(std::size_t id);
/// Whether a file name is a status file's (`fsweep run --fresh` deletes them).
[[nodiscard]] bool is_search_status_file(std::string_view name);
/// The certificate's format, its header's "format".
inline constexpr char kCertificateFormat[] = "fsweep weight search certificate 1";

// ---- Column names readers look up.
inline constexpr char kSearchIdColumn[] = "search_id";
inline constexpr char kBehaviourIdColumn[] = "behaviour_id";
inline constexpr char kInstanceColumn[] = "instance";
inline constexpr char kRankColumn[] = "rank";
inline constexpr char kVectorsColumn[] = "vectors";
inline constexpr char kObjectiveColumn[] = "objective";

// ---- Headers, in column order.
/// behaviours.csv (a row per behaviour and instance): search_id, behaviour_id, vectors, the
/// representative's weights, each weight's .min and .max over the behaviour's vectors, objective,
/// instance, map, seed, then runs.csv's metric columns and optimal_distance_m, competitive_ratio.
[[nodiscard]] std::vector<std::string> behaviours_columns(std::span<const std::string> weights);
/// search_summary.csv (mode all, a row per search): the search, its vectors and behaviours, the
/// vectors of each end reason, and the nine statistics of each metric over all vectors.
[[nodiscard]] std::vector<std::string> search_summary_columns();
/// search_best.csv: search_id, rank, behaviour_id, vectors, vectors_better, objective, then the
/// representative's weights (the columns after objective).
[[nodiscard]] std::vector<std::string> search_best_columns(std::span<const std::string> weights);
/// The weight names of a search_best.csv header: its columns after objective.
[[nodiscard]] std::vector<std::string> search_best_weights(const std::vector<std::string>& header);
/// search_ranks.csv (a row per `rank` vector): search_id, the weights, behaviour_id, objective,
/// rank, vectors_better, vectors_tied, percentile.
[[nodiscard]] std::vector<std::string> search_ranks_columns(std::span<const std::string> weights);
/// search_anytime.csv (mode best, a row per report of a search's state): search_id, elapsed_s,
/// status, resolved_vectors, vectors, open_branches, best, bound, gap, relative_gap.
[[nodiscard]] std::vector<std::string> search_anytime_columns();
/// search_heatmaps.csv: search_id, weight_a, weight_b, value_a, value_b, best_objective, behaviour_id.
[[nodiscard]] std::vector<std::string> search_heatmaps_columns();
/// vectors.csv (write_vectors): search_id, the weights, behaviour_id.
[[nodiscard]] std::vector<std::string> vectors_columns(std::span<const std::string> weights);

}  // namespace report
}  // namespace fsweep
