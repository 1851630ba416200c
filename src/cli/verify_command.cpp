/// @file verify_command.cpp
/// `fsweep verify DIR`: checks the certificates of a sweep's exact weight searches of mode best
/// (verify/certificate_check.hpp). The instances' specs come from the sweep that manifest.json
/// records: every search of mode best it defines must have finished with a certificate that is
/// that search's (its box, objective, direction and instances) and that searches.json reports
/// (the optimum, the counts). Exit 0 every certificate verified, 1 one did not or a search has
/// none (each problem named by line and region), 2 bad input (a malformed line, a certificate of
/// another search).

#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/output_dir.hpp"
#include "cli/problem_list.hpp"
#include "core/config_error.hpp"
#include "core/files.hpp"
#include "core/json_text.hpp"
#include "core/readable_number.hpp"
#include "report/runs_schema.hpp"
#include "report/search_schema.hpp"
#include "sweep/manifest.hpp"
#include "sweep/sweep_plan.hpp"
#include "verify/certificate_check.hpp"

namespace fsweep::cli {
namespace {

struct VerifyCommandOptions {
  std::string dir;
  VerifyOptions verify;
};

/// searches.json's records by search id (none when the file is missing: no search finished).
std::map<std::size_t, nlohmann::json> search_records(const std::string& dir) {
  const std::string path = dir + "/" + kSearchesFile;
  const std::optional<std::string> text = read_file(path);
  if (!text) return {};  // no search has finished: each is "not finished" (why_no_certificate())
  nlohmann::json searches;
  try {
    searches = parse_json_unique_keys(*text, path);
  } catch (const nlohmann::json::exception& e) {
    throw ConfigError(path, std::string("not JSON: ") + e.what());
  }
  if (!searches.is_object() || !searches.contains("searches") || !searches.at("searches").is_array())
    throw ConfigError(path, "not a searches file: an object whose \"searches\" is an array");
  std::map<std::size_t, nlohmann::json> out;
  for (const nlohmann::json& s : searches.at("searches")) {
    const nlohmann::json& id = s.is_object() ? s.value(kSearchIdColumn, nlohmann::json()) : nlohmann::json();
    if (!id.is_number_unsigned() || !out.emplace(id.get<std::size_t>(), s).second)
      throw ConfigError(path, "a record without its own search_id (an integer >= 0, once each): " +
                                  s.dump(-1).substr(0, 200));
  }
  return out;
}

/// Why search `id` has no certificate to check ("" when its record names one).
std::string why_no_certificate(const std::string& dir, std::size_t id,
                               const std::map<std::size_t, nlohmann::json>& records) {
  const auto it = records.find(id);
  if (it == records.end()) {
    const std::optional<std::string> status = read_file(dir + "/" + search_status_file(id));
    return "not finished: no record in searches.json" +
           (status ? " (" + search_status_file(id) +
                         " holds where it stopped; `fsweep run` on the same sweep and DIR finishes it)"
                   : std::string());
  }
  const nlohmann::json& c = it->second.value("certificate", nlohmann::json());
  if (!c.is_object()) return "its record in searches.json has no certificate";
  if (!c.value("file", nlohmann::json()).is_string()) {
    const nlohmann::json& why = c.value("why_not", nlohmann::json());
    return "its record in searches.json names no certificate file" +
           (why.is_string() ? ": " + why.get<std::string>() : std::string());
  }
  return {};
}

/// Throws ConfigError (path:1) unless `header` is search `id` of `plan` (unit `unit`) as the sweep
/// in manifest.json defines it: its strategy entry, map class, box, objective and its direction,
/// and every instance. Returns the instances' specs.
std::vector<RunSpec> instance_specs(const SweepPlan& plan, const SearchUnit& unit, std::size_t id,
                                    const CertificateHeader& header, const std::string& path) {
  const WeightSearch& search = *plan.strategies().at(unit.entry).search;
  const Objective& objective = *find_objective(plan.objective());
  const auto differs = [&](const std::string& field, const std::string& certificate,
                           const std::string& sweep) {
    return ConfigError(path + ":1", field + " " + certificate +
                                        ", where the sweep's (manifest.json) search " + std::to_string(id) +
                                        " has " + sweep + ": the certificate is another search's");
  };
  if (header.search_id != id)
    throw differs("search_id", std::to_string(header.search_id), std::to_string(id));
  if (header.strategy_label != plan.strategies().at(unit.entry).label)
    throw differs("strategy_label", header.strategy_label, plan.strategies().at(unit.entry).label);
  if (header.map_class != unit.map_class) throw differs("map_class", header.map_class, unit.map_class);
  if (header.weights != search.weights) {
    throw differs("weights", nlohmann::json(header.weights).dump(), nlohmann::json(search.weights).dump());
  }
  if (header.values != search.values) {
    throw differs("the box", nlohmann::json(header.values).dump(-1).substr(0, 120),
                  nlohmann::json(search.values).dump(-1).substr(0, 120));
  }
  const bool minimize = objective.direction == Direction::Minimize;
  if (header.objective != objective.name || header.objective_column != objective.column ||
      header.minimize != minimize) {
    throw differs("objective", header.objective + " (" + (header.minimize ? "minimize" : "maximize") + ")",
                  std::string(objective.name) + " (" + (minimize ? "minimize" : "maximize") + ")");
  }
  const std::size_t instances = unit.maps.size() * static_cast<std::size_t>(plan.repetitions());
  if (header.instances.size() != instances) {
    throw differs("instances", std::to_string(header.instances.size()),
                  std::to_string(instances) + " (maps x repetitions)");
  }
  std::vector<RunSpec> specs;
  for (std::size_t i = 0; i < instances; ++i) {
    if (plan.search_instance_json(unit, i) != header.instances.at(i)) {
      throw ConfigError(path + ":1",
                        "instance " + std::to_string(i) +
                            " is not the sweep's (manifest.json): the certificate is another search's");
    }
    specs.push_back(plan.search_instance(unit, i));
  }
  return specs;
}

/// What searches.json's record says of the certificate but the check did not find.
std::vector<std::string> record_problems(const nlohmann::json& record, const CertificateHeader& header,
                                         const CertificateCheck& c) {
  const nlohmann::json& note = record.at("certificate");
  std::vector<std::string> out;
  const nlohmann::json optimum =
      std::isnan(header.optimum) ? nlohmann::json() : nlohmann::json(header.optimum);
  if (note.value("optimum", nlohmann::json("missing")) != optimum) {
    out.push_back("searches.json gives the optimum " +
                  note.value("optimum", nlohmann::json("missing")).dump() + ", the certificate " +
                  optimum.dump());
  }
  const auto count = [&](const char* key, std::uint64_t found) {
    const nlohmann::json& given = note.value(key, nlohmann::json());
    if (!given.is_number_unsigned() || given.get<std::uint64_t>() != found) {
      out.push_back("searches.json gives " + std::string(key) + " " + given.dump() + ", the certificate " +
                    std::to_string(found));
    }
  };
  count("regions", c.regions);
  count("optimal_vectors", c.optimal_vectors);
  return out;
}

/// Prints what the check of one certificate found (stdout) and its problems (stderr); true when
/// it verified.
bool report(const std::string& path, const CertificateHeader& header, const CertificateCheck& c,
            const VerifyCommandOptions& o) {
  const auto count = [](std::uint64_t n) { return readable_number(static_cast<double>(n), 16); };
  std::cout << path << ": search " << header.search_id << " (" << header.strategy_label << ", "
            << header.map_class << "), " << count(header.vectors) << " vectors, " << count(c.regions)
            << " regions (" << count(c.finished) << " finished, " << count(c.pruned) << " pruned)\n";
  std::cout << "  cover: the regions' counts " << (c.counts_match ? "sum" : "do not sum") << " to the box's"
            << (!c.overlap_checked ? " (overlap not checked: a box above 2^33 vectors)"
                : c.overlap_found  ? ", and some vector is in two regions"
                                   : ", and no vector is in two regions")
            << '\n';
  if (std::isnan(header.optimum)) {
    std::cout << "  optimum none (" << header.objective << "): no vector's runs have a value\n";
  } else {
    std::cout << "  optimum " << readable_number(header.optimum, 8) << " (" << header.objective
              << "): " << count(c.optimal_regions) << " optimal region(s), " << count(c.optimal_vectors)
              << " vectors\n";
  }
  std::cout << "  re-simulated " << count(c.resimulated) << " of " << count(c.regions) << " regions"
            << (c.sampled ? " (the optimal ones and a sample, seed " + std::to_string(o.verify.seed) + ")"
                          : "")
            << ": " << count(c.decisions_checked) << " decisions checked over their regions ("
            << count(c.boxes_by_corners) << " boxes by their corners, " << count(c.boxes_by_points)
            << " point by point)\n";
  if (c.problems.empty()) {
    std::cout << "  verified\n";
    return true;
  }
  std::cerr << "fsweep verify: " << path << ": " << c.problems.size() << " problem(s):\n";
  print_problems(std::cerr, c.problems);
  return false;
}

int run_verify(const VerifyCommandOptions& o) {
  if (!std::filesystem::is_directory(o.dir))
    throw ConfigError(o.dir, "no such directory (DIR: a sweep's output directory)");
  check_output_dir(o.dir, OutputKind::Sweep, "DIR");
  const std::string manifest_path = o.dir + "/manifest.json";
  const std::optional<nlohmann::json> manifest = read_manifest(manifest_path);
  if (!manifest || !manifest->contains("sweep"))
    throw ConfigError(manifest_path, "missing or without its sweep");
  const SweepPlan plan =
      SweepPlan::from_json(manifest->at("sweep"), manifest->value("sweep_file", std::string()));
  if (find_objective(plan.objective()) == nullptr)
    throw ConfigError(manifest_path, "objective '" + plan.objective() + "' unknown to this build");
  // Every search of mode best the sweep defines, each by its own certificate.
  const std::vector<SearchUnit> units = plan.search_units();
  std::vector<std::size_t> best;
  for (std::size_t id = 0; id < units.size(); ++id) {
    if (plan.strategies().at(units[id].entry).search->mode == WeightSearch::Mode::Best) best.push_back(id);
  }
  if (best.empty()) {
    throw ConfigError(manifest_path,
                      "the sweep has no exact weight search of mode best, so no certificate "
                      "to check (mode all writes none)");
  }
  const std::map<std::size_t, nlohmann::json> records = search_records(o.dir);
  bool all_verified = true;
  for (const std::size_t id : best) {
    if (const auto it = records.find(id); it != records.end() && it->second.is_object()) {
      const nlohmann::json shard = it->second.value("shard", nlohmann::json());
      if (shard.is_object() && shard.value("count", 1) > 1) {
        throw ConfigError(o.dir + "/" + kSearchesFile,
                          "search " + std::to_string(id) + " here is a shard's part (shard " + shard.dump() +
                              "): `fsweep merge` on the shards' parent directory writes its certificate; "
                              "verify that directory");
      }
    }
    if (const std::string why = why_no_certificate(o.dir, id, records); !why.empty()) {
      std::cerr << "fsweep verify: search " << id << " (" << plan.strategies().at(units[id].entry).label
                << ", " << units[id].map_class << "): nothing verified: " << why << '\n';
      all_verified = false;
      continue;
    }
    const nlohmann::json& record = records.at(id);
    const std::string file = record.at("certificate").at("file").get<std::string>();
    if (file != search_certificate_file(id)) {
      throw ConfigError(o.dir + "/" + kSearchesFile, "search " + std::to_string(id) +
                                                         "'s certificate file '" + file + "'; allowed: '" +
                                                         search_certificate_file(id) + "' beside it");
    }
    const std::string path = o.dir + "/" + file;
    const CertificateHeader header = read_certificate_header(path);
    const std::vector<RunSpec> specs = instance_specs(plan, units[id], id, header, path);
    CertificateCheck c = check_certificate(path, header, specs, o.verify);
    for (std::string& p : record_problems(record, header, c)) c.problems.push_back(std::move(p));
    all_verified = report(path, header, c, o) && all_verified;
  }
  return all_verified ? 0 : 1;
}

}  // namespace

Command add_verify_command(CLI::App& app) {
  auto o = std::make_shared<VerifyCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "verify",
      "Check the certificates of a sweep's exact weight searches of mode best (search_certificate_*.jsonl)");
  sub->add_option("DIR", o->dir, "Sweep output directory with searches.json and its certificates")
      ->required();
  sub->add_option("--threads", o->verify.threads,
                  "Threads for the re-simulations (the result does not depend on them)")
      ->check(CLI::Range(1, 1024))
      ->default_val(1);
  sub->add_option(
         "--full-limit", o->verify.full_limit,
         "Boxes of at most this many vectors have every region re-simulated; larger ones the optimal "
         "regions and a sample")
      ->default_val(1'000'000);
  sub->add_option("--sample", o->verify.sample,
                  "Regions re-simulated besides the optimal ones in a larger box")
      ->default_val(1000);
  sub->add_option("--seed", o->verify.seed, "Seed of the sample")->default_val(1);
  return [o] { return run_verify(*o); };
}

}  // namespace fsweep::cli
