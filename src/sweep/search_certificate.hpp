#pragma once
/// @file search_certificate.hpp
/// Writes the certificate of an exact weight search of mode best: the partition of its box into
/// the regions its journal (or its shards' journals) holds, each a finished behaviour with its
/// objective or a pruned region with its bound and the state that bound was taken in
/// (docs/dev/weight-search-design.md, "The certificate", documents the format; `fsweep verify`
/// checks it).

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "weightsearch/search_journal.hpp"
#include "weightsearch/weight_grid.hpp"

namespace fsweep {
inline namespace sweep {

/// Where a certificate's regions come from.
struct CertificateSource {
  /// The journals that hold the search's lines: its own, or its shards'.
  std::vector<std::string> journals;
  /// The search's lines (key, grid, instances, cells per instance).
  JournalShape shape;
  /// The position of the objective's cell in a behaviour line's cells.
  std::size_t objective_cell = 0;
  /// 1 for a minimised objective, -1 for a maximised one (journaled leaves hold values as branch
  /// and bound minimises them).
  double sign = 1.0;
};

/// Writes the certificate to `path` (temp file and rename): `header` (the search's identity,
/// box, objective, optimum and instances) as its first line, then one line per region. When the
/// regions do not cover the box (a journal written before leaves were journaled), nothing is
/// written. Returns the searches.json note: the file's name and its region count, or null and why not.
[[nodiscard]] nlohmann::json write_search_certificate(const std::string& path, const nlohmann::json& header,
                                                      const CertificateSource& source);

}  // namespace sweep
}  // namespace fsweep
