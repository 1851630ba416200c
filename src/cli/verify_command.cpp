/// @file verify_command.cpp
/// `fsweep verify DIR`: checks the certificates of a sweep's exact weight searches of mode best
/// (verify/certificate_check.hpp). The instances' specs come from the sweep that manifest.json
/// records, and must be those the certificate lists. Exit 0 every certificate verified, 1 one
/// did not (each problem named by line and region), 2 bad input (no certificate, a malformed line).

#include <filesystem>
#include <iostream>
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

/// The searches.json records of `dir` with a certificate file.
std::vector<nlohmann::json> certified_searches(const std::string& dir) {
  const std::string path = dir + "/" + kSearchesFile;
  const std::optional<std::string> text = read_file(path);
  if (!text) throw ConfigError(path, "missing: DIR holds no finished exact weight search");
  std::vector<nlohmann::json> out;
  const nlohmann::json searches = parse_json_bounded(*text, path);
  for (const nlohmann::json& s : searches.value("searches", nlohmann::json::array())) {
    const nlohmann::json& c = s.value("certificate", nlohmann::json());
    if (c.is_object() && c.contains("file") && c.at("file").is_string()) out.push_back(s);
  }
  if (out.empty()) {
    throw ConfigError(path,
                      "no search of mode best with a certificate file (mode all has none; a search "
                      "resumed from a journal of an older version has none: rerun it with --fresh)");
  }
  return out;
}

/// The instances' specs of certificate `header` from `plan`, checked against the header's.
std::vector<RunSpec> instance_specs(const SweepPlan& plan, const CertificateHeader& header,
                                    const std::string& path) {
  const std::vector<SearchUnit> units = plan.search_units();
  if (header.search_id >= units.size()) {
    throw ConfigError(path + ":1", "search_id " + std::to_string(header.search_id) + "; the sweep has " +
                                       std::to_string(units.size()) + " searches");
  }
  const SearchUnit& unit = units[header.search_id];
  std::vector<RunSpec> specs;
  for (std::size_t i = 0; i < header.instances.size(); ++i) {
    if (plan.search_instance_json(unit, i) != header.instances.at(i)) {
      throw ConfigError(path + ":1",
                        "instance " + std::to_string(i) +
                            " is not the sweep's (manifest.json): the certificate is another search's");
    }
    specs.push_back(plan.search_instance(unit, i));
  }
  return specs;
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
  bool all_verified = true;
  for (const nlohmann::json& search : certified_searches(o.dir)) {
    const std::string path = o.dir + "/" + search.at("certificate").at("file").get<std::string>();
    const CertificateHeader header = read_certificate_header(path);
    const std::vector<RunSpec> specs = instance_specs(plan, header, path);
    const CertificateCheck c = check_certificate(path, header, specs, o.verify);
    const auto count = [](std::uint64_t n) { return readable_number(static_cast<double>(n), 16); };
    std::cout << path << ": search " << header.search_id << " (" << header.strategy_label << ", "
              << header.map_class << "), " << count(header.vectors) << " vectors, " << count(c.regions)
              << " regions (" << count(c.finished) << " finished, " << count(c.pruned) << " pruned)\n";
    std::cout << "  cover: the regions' counts " << (c.counts_match ? "sum" : "do not sum") << " to the box's"
              << (!c.overlap_checked ? " (overlap not checked: a box above 2^33 vectors)"
                  : c.overlap_found  ? ", and some vector is in two regions"
                                     : ", and no vector is in two regions")
              << '\n';
    std::cout << "  optimum " << readable_number(header.optimum, 8) << " (" << header.objective
              << "): " << count(c.optimal_regions) << " optimal region(s), " << count(c.optimal_vectors)
              << " vectors\n";
    std::cout << "  re-simulated " << count(c.resimulated) << " of " << count(c.regions) << " regions"
              << (c.sampled ? " (the optimal ones and a sample, seed " + std::to_string(o.verify.seed) + ")"
                            : "")
              << ": " << count(c.decisions_checked) << " decisions checked over their regions ("
              << count(c.boxes_by_corners) << " boxes by their corners, " << count(c.boxes_by_points)
              << " point by point)\n";
    if (c.problems.empty()) {
      std::cout << "  verified\n";
      continue;
    }
    all_verified = false;
    std::cerr << "fsweep verify: " << path << ": " << c.problems.size() << " problem(s):\n";
    print_problems(std::cerr, c.problems);
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
