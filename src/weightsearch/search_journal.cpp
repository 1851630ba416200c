#include "weightsearch/search_journal.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/config_error.hpp"
#include "core/json_text.hpp"
#include "core/random.hpp"

namespace fsweep {
inline namespace weightsearch {
namespace {

using nlohmann::json;

/// 16 hex digits as a number (a trace or a subtree id).
std::uint64_t hex_id(const json& j, const char* what) {
  const std::string hex = j.get<std::string>();
  if (hex.size() != 16) throw std::runtime_error(std::string("bad ") + what);
  return std::stoull(hex, nullptr, 16);
}

/// A part of a journaled region: its block and its points as point_runs(), or (journals
/// written before the point runs, format 3 too) as the 64 words of its bits in hexadecimal.
WeightRegion::Part part_of(const json& p) {
  WeightRegion::Part part;
  part.block = p.at(0).get<std::uint32_t>();
  const json& points = p.at(1);
  if (points.is_array()) {
    part.bits = bits_of_runs(points.get<std::vector<std::uint32_t>>());
  } else {
    const std::string hex = points.get<std::string>();
    if (hex.size() != part.bits.size() * 16) throw std::runtime_error("bad part");
    for (std::size_t w = 0; w < part.bits.size(); ++w) {
      part.bits[w] = std::stoull(hex.substr(w * 16, 16), nullptr, 16);
    }
  }
  return part;
}

SubtreeTally tally_of(const json& j) {
  SubtreeTally t;
  t.vectors = j.at("vectors").get<std::uint64_t>();
  t.behaviours = j.at("behaviours").get<std::uint64_t>();
  t.pruned_regions = j.at("pruned_regions").get<std::uint64_t>();
  t.pruned_vectors = j.at("pruned_vectors").get<std::uint64_t>();
  const json& bound = j.at("smallest_pruned_bound");
  if (!bound.is_null()) t.smallest_pruned_bound = bound.get<double>();
  return t;
}

/// A line's region ("boxes" and "parts"), checked to lie in the search's box and hold a vector.
WeightRegion region_of(const json& j, const WeightGrid& grid) {
  WeightRegion region;
  for (const json& box_json : j.at("boxes")) {
    WeightRegion::Box box;
    for (std::size_t k = 0; k < 4; ++k) {
      box.lo[k] = box_json.at(k).get<std::uint32_t>();
      box.hi[k] = box_json.at(k + 4).get<std::uint32_t>();
    }
    region.whole.push_back(box);
  }
  for (const json& p : j.at("parts")) region.parts.push_back(part_of(p));
  if (!grid.holds(region)) throw std::runtime_error("a region outside the search's box");
  if (region.empty()) throw std::runtime_error("an empty region");
  return region;
}

/// The region's boxes and parts as a line holds them.
void put_region(json& line, const WeightRegion& region) {
  json boxes = json::array();
  for (const WeightRegion::Box& b : region.whole) {
    boxes.push_back({b.lo[0], b.lo[1], b.lo[2], b.lo[3], b.hi[0], b.hi[1], b.hi[2], b.hi[3]});
  }
  json parts = json::array();
  for (const WeightRegion::Part& p : region.parts) parts.push_back({p.block, point_runs(p.bits)});
  line["boxes"] = std::move(boxes);
  line["parts"] = std::move(parts);
}

/// A leaf line's leaf.
JournaledLeaf leaf_of(const json& j, const JournalShape& shape) {
  JournaledLeaf out;
  const std::string kind = j.at("leaf").get<std::string>();
  if (kind != "pruned" && kind != "beaten") throw std::runtime_error("a leaf neither pruned nor beaten");
  out.kind = kind == "pruned" ? CertifiedLeaf::Kind::Pruned : CertifiedLeaf::Kind::Beaten;
  out.region = region_of(j, *shape.grid);
  out.choices = j.at("choices").get<std::vector<int>>();
  out.vectors = shape.grid->count(out.region);
  const json& value = j.at("value");
  out.value = value.is_null() ? std::numeric_limits<double>::quiet_NaN() : value.get<double>();
  if (out.kind == CertifiedLeaf::Kind::Pruned) {
    out.steps = j.at("steps").get<std::vector<std::uint64_t>>();
    if (out.steps.size() != shape.instances) throw std::runtime_error("not a leaf of this search");
  } else {
    out.trace = hex_id(j.at("trace"), "trace");
  }
  return out;
}

/// A behaviour line's behaviour, checked against `shape`.
JournaledBehaviour behaviour_of(const json& j, const JournalShape& shape) {
  JournaledBehaviour out;
  Behaviour& b = out.behaviour;
  b.choices = j.at("choices").get<std::vector<int>>();
  b.trace = hex_id(j.at("trace"), "trace");
  for (const json& row : j.at("cells")) {
    if (row.size() + 1 == shape.cells && shape.added_cell < shape.cells) {
      std::vector<std::string> cells = row.get<std::vector<std::string>>();
      cells.insert(cells.begin() + static_cast<std::ptrdiff_t>(shape.added_cell), std::string());
      out.cells.push_back(std::move(cells));
      continue;
    }
    if (row.size() != shape.cells) throw std::runtime_error("another build's columns");
    out.cells.push_back(row.get<std::vector<std::string>>());
  }
  if (out.cells.size() != shape.instances) throw std::runtime_error("not a behaviour of this search");
  const WeightGrid& grid = *shape.grid;
  b.region = region_of(j, grid);
  b.vectors = grid.count(b.region);
  b.representative = grid.lexmin(b.region);
  b.bounds = grid.bounds(b.region);
  return out;
}

}  // namespace

std::unordered_map<std::uint64_t, SubtreeTally> SearchJournal::read(
    const std::string& path, const JournalShape& shape, JournalDamage damage, std::string_view hint,
    const std::function<void(JournaledBehaviour&&)>& each,
    const std::function<void(JournaledLeaf&&)>& each_leaf, std::size_t* other_lines) {
  std::unordered_map<std::uint64_t, SubtreeTally> done;
  std::ifstream in(path, std::ios::binary);
  if (!in) return done;
  std::string line;
  std::uintmax_t kept_bytes = 0;  // the lines before a damaged one (a journal may hold gigabytes)
  std::size_t number = 0;
  bool torn = false;
  while (std::getline(in, line)) {
    ++number;
    try {
      if (in.eof()) throw std::runtime_error("no newline");
      const json j = parse_json_bounded(line, path);
      const std::string key = j.at("key").get<std::string>();
      if (other_lines != nullptr && !shape.counted_key.empty() && key == shape.counted_key) ++*other_lines;
      if (key == shape.key) {
        if (j.contains("done")) {
          const std::uint64_t id = hex_id(j.at("done"), "subtree id");  // checked first: its error names it
          done.emplace(id, tally_of(j));
        } else if (j.contains("leaf")) {
          JournaledLeaf leaf = leaf_of(j, shape);
          if (each_leaf) each_leaf(std::move(leaf));
        } else {
          each(behaviour_of(j, shape));
        }
      }
    } catch (const std::exception& e) {
      if (damage == JournalDamage::Refuse) {
        throw ConfigError(path + ":" + std::to_string(number), std::string(e.what()) + std::string(hint));
      }
      std::fprintf(stderr,
                   "fsweep: %s:%zu: %s; this line and the rest are dropped (the search redoes them)\n",
                   path.c_str(), number, e.what());
      torn = true;
      break;
    }
    kept_bytes += line.size() + 1;
  }
  in.close();
  if (torn) {
    std::error_code ec;
    std::filesystem::resize_file(path, kept_bytes, ec);
    if (ec) throw ConfigError(path, "cannot cut off its damaged lines: " + ec.message());
  }
  return done;
}

void SearchJournal::append(const std::string& key, const Behaviour& behaviour,
                           const std::vector<std::vector<std::string>>& cells) {
  json line{
      {"key", key}, {"trace", hex64(behaviour.trace)}, {"choices", behaviour.choices}, {"cells", cells}};
  put_region(line, behaviour.region);
  file_.write(line.dump() + '\n');
}

void SearchJournal::append_leaf(const std::string& key, const CertifiedLeaf& leaf) {
  const bool pruned = leaf.kind == CertifiedLeaf::Kind::Pruned;
  json line{{"key", key},
            {"leaf", pruned ? "pruned" : "beaten"},
            {"choices", leaf.choices},
            {"value", std::isnan(leaf.value) ? json(nullptr) : json(leaf.value)}};
  if (pruned) {
    line["steps"] = leaf.steps;
  } else {
    line["trace"] = hex64(leaf.trace);
  }
  put_region(line, *leaf.region);
  file_.write(line.dump() + '\n');
}

void SearchJournal::append_done(const std::string& key, std::uint64_t id, const SubtreeTally& tally) {
  file_.write(
      json{{"key", key},
           {"done", hex64(id)},
           {"vectors", tally.vectors},
           {"behaviours", tally.behaviours},
           {"pruned_regions", tally.pruned_regions},
           {"pruned_vectors", tally.pruned_vectors},
           {"smallest_pruned_bound",
            std::isfinite(tally.smallest_pruned_bound) ? json(tally.smallest_pruned_bound) : json(nullptr)}}
          .dump() +
      '\n');
}

}  // namespace weightsearch
}  // namespace fsweep
