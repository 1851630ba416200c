#pragma once
/// @file search_journal.hpp
/// The exact weight search's journal (`search_journal.jsonl`): what a search finished, one JSON
/// line each, written at once, so that a killed search resumes where it stopped and shards
/// merge (sweep/weight_search_runner.hpp runs both). One file serves every search of a sweep;
/// each line carries its search's key, a hash of everything that makes the search what it is
/// (the caller's; it ends with kFormat, so a journal of another format is never read as this one).
///
/// Two kinds of line (documented in docs/dev/weight-search-design.md, "The journal"):
/// - a finished behaviour: `{"key", "trace" (16 hex digits), "boxes" ([lo..., hi...] per whole
///   box), "parts" ([block, point runs] per part of a block, WeightGrid's point_runs()),
///   "choices" (the region tree path), "cells" (per instance, its metric cells as text)}`;
/// - a finished subtree of the region tree: `{"key", "done" (its id, 16 hex digits), "vectors",
///   "behaviours", "pruned_regions", "pruned_vectors", "smallest_pruned_bound" (null: none)}`;
/// - branch and bound's other leaves (CertifiedLeaf): `{"key", "leaf" ("pruned" or "beaten"),
///   "boxes", "parts", "choices", "value" (null: none), "steps" (pruned: per instance),
///   "trace" (beaten)}`. Journals written before these lines resume as ever; their searches
///   have no certificate.

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/append_file.hpp"
#include "weightsearch/exact_search.hpp"
#include "weightsearch/weight_grid.hpp"

namespace fsweep {
inline namespace weightsearch {

/// A finished behaviour as the journal holds it: the behaviour without its runs, and per
/// instance the cells they were formatted into (the caller's columns, as text).
struct JournaledBehaviour {
  Behaviour behaviour;
  std::vector<std::vector<std::string>> cells;
};

/// A leaf line: the CertifiedLeaf, its region owned, its vector count from the grid.
struct JournaledLeaf {
  CertifiedLeaf::Kind kind = CertifiedLeaf::Kind::Pruned;
  WeightRegion region;
  std::vector<int> choices;
  std::uint64_t vectors = 0;
  double value = 0.0;
  std::vector<std::uint64_t> steps;
  std::uint64_t trace = 0;
};

/// What a search's lines must be to be read as its own.
struct JournalShape {
  /// The search's key (the caller's hash; see the file comment).
  std::string key;
  /// Its box: every region must lie in it. Read behaviours get their vectors, representative
  /// and bounds from it.
  const WeightGrid* grid = nullptr;
  /// Instances (rows of cells) per behaviour, and cells per row.
  std::size_t instances = 0;
  std::size_t cells = 0;
  /// A cell that lines of older journals lack (a column added since, empty for them): a row one
  /// cell short gets an empty cell inserted here. cells: none.
  std::size_t added_cell = std::numeric_limits<std::size_t>::max();
  /// Another key whose lines are only counted (SearchJournal::read's `other_lines`): the same
  /// search's key in the format before (SearchJournal::kPreviousFormat). Empty: none.
  std::string counted_key{};
};

/// What to do with a line that does not parse or does not fit the shape.
enum class JournalDamage {
  /// A killed search's torn last line: this line and every one after it are dropped (stderr
  /// names the line), and the file is cut before it, so that new lines follow complete ones.
  Repair,
  /// A finished search's journal (a shard being merged) must be whole: ConfigError naming the
  /// file and line, followed by the caller's hint; the file is left as it is.
  Refuse,
};

class SearchJournal {
 public:
  /// The journal's format, the last part of every search's key (format_for()). 4: the region
  /// tree of a class of several instances whose branches advance every instance before they
  /// split (exact_search.cpp, Explorer::explore). 3 (kPreviousFormat): regions' parts as point
  /// runs and finished subtrees, in the tree that split at the first unfinished instance's
  /// decisions; for one instance the two trees are the same, so such searches keep format 3.
  /// Lines of formats 1 and 2, and a class's lines of format 3, are not read as the search's.
  static constexpr std::string_view kFormat = "journal 4";
  static constexpr std::string_view kPreviousFormat = "journal 3";
  /// The format of the lines of a search of `instances` instances.
  [[nodiscard]] static constexpr std::string_view format_for(std::size_t instances) {
    return instances == 1 ? kPreviousFormat : kFormat;
  }

  /// Reads the lines of `shape.key` in the journal at `path` (missing: nothing): each finished
  /// behaviour goes to `each` as it is read (so a caller may drop what it need not keep), and the
  /// finished subtrees are returned by id. Lines of other keys are parsed (a damaged one is
  /// damage too) and passed over.
  /// Each leaf line goes to `each_leaf` (may be empty: leaf lines are then only checked).
  /// `other_lines` (may be null) counts the lines of `shape.counted_key`.
  [[nodiscard]] static std::unordered_map<std::uint64_t, SubtreeTally> read(
      const std::string& path, const JournalShape& shape, JournalDamage damage, std::string_view hint,
      const std::function<void(JournaledBehaviour&&)>& each,
      const std::function<void(JournaledLeaf&&)>& each_leaf = {}, std::size_t* other_lines = nullptr);

  /// Opens the journal at `path` for appending (created if missing); throws IoError naming it
  /// and the OS error when it cannot be. The appends throw IoError too, each line whole or not
  /// at all (core/append_file.hpp).
  explicit SearchJournal(std::string path) : file_(std::move(path)) { file_.open(); }

  /// Appends a finished behaviour's line (its region, choices and trace) with its `cells`.
  void append(const std::string& key, const Behaviour& behaviour,
              const std::vector<std::vector<std::string>>& cells);
  /// Appends a leaf's line.
  void append_leaf(const std::string& key, const CertifiedLeaf& leaf);
  /// Appends the line of a finished subtree `id` with its tally.
  void append_done(const std::string& key, std::uint64_t id, const SubtreeTally& tally);

  [[nodiscard]] const std::string& path() const { return file_.path(); }

 private:
  AppendFile file_;
};

}  // namespace weightsearch
}  // namespace fsweep
