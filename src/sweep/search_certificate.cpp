#include "sweep/search_certificate.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>

#include "core/random.hpp"
#include "core/replacing_file.hpp"
#include "report/search_objective.hpp"

namespace fsweep {
inline namespace sweep {
namespace {

using nlohmann::json;

/// A region as the certificate lists it: boxes of grid indices, `[lo_1..lo_n, hi_1..hi_n]`
/// inclusive, over the grid's n weights.
json index_boxes(const WeightGrid& grid, const WeightRegion& region) {
  const auto n = static_cast<std::size_t>(grid.weights());
  json boxes = json::array();
  for (const WeightGrid::IndexBox& b : grid.index_boxes(region)) {
    json box = json::array();
    for (std::size_t k = 0; k < n; ++k) box.push_back(b.lo[k]);
    for (std::size_t k = 0; k < n; ++k) box.push_back(b.hi[k]);
    boxes.push_back(std::move(box));
  }
  return boxes;
}

json value_json(double v) { return std::isnan(v) ? json(nullptr) : json(v); }

}  // namespace

json write_search_certificate(const std::string& path, const json& header, const CertificateSource& source) {
  const WeightGrid& grid = *source.shape.grid;
  std::uint64_t vectors = 0;
  std::uint64_t regions = 0;
  ReplacingFile out(path);  // put in place only when the regions partition the box
  out.write(header.dump() + '\n');
  const auto put = [&](json line, const WeightRegion& region, std::uint64_t count) {
    line["boxes"] = index_boxes(grid, region);
    out.write(line.dump() + '\n');
    vectors += count;
    ++regions;
  };
  for (const std::string& journal : source.journals) {
    (void)SearchJournal::read(
        journal, source.shape, JournalDamage::Refuse, "",
        [&](JournaledBehaviour&& b) {
          // The class mean of the objective's cells, as the search computed it.
          double sum = 0.0;
          for (const auto& cells : b.cells) {
            sum += metric_number(cells.at(source.objective_cell));
          }
          put(json{{"kind", "finished"},
                   {"value", value_json(sum / static_cast<double>(b.cells.size()))},
                   {"choices", b.behaviour.choices},
                   {"trace", hex64(b.behaviour.trace)}},
              b.behaviour.region, b.behaviour.vectors);
        },
        [&](JournaledLeaf&& leaf) {
          json line{{"choices", leaf.choices}, {"value", value_json(source.sign * leaf.value)}};
          if (leaf.kind == CertifiedLeaf::Kind::Pruned) {
            line["kind"] = "pruned";
            line["steps"] = leaf.steps;
          } else {
            line["kind"] = "finished";
            line["trace"] = hex64(leaf.trace);
          }
          put(std::move(line), leaf.region, leaf.vectors);
        });
  }
  if (vectors != grid.size()) {
    const std::string cause =
        vectors < grid.size()
            ? "lines are missing (a journal cut after its search finished, or part of it written by a "
              "version that did not journal pruned regions)"
            : "some overlap: a version that pruned above the regions it had journaled resumed it";
    return json{{"file", nullptr},
                {"why_not", "the journal's regions hold " + std::to_string(vectors) + " of the " +
                                std::to_string(grid.size()) + " vectors: " + cause +
                                "; rerun with --fresh for a certificate"}};
  }
  out.commit();
  return json{{"file", std::filesystem::path(path).filename().string()}, {"regions", regions}};
}

}  // namespace sweep
}  // namespace fsweep
