#include "cli/output_dir.hpp"

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <system_error>
#include <vector>

#include "core/config_error.hpp"
#include "core/json_text.hpp"
#include "sweep/manifest.hpp"
#include "sweep/merge.hpp"
#include "sweep/optimum_table.hpp"

namespace fsweep {
namespace {

namespace fs = std::filesystem;

/// The files of `names` that exist in `dir`, joined for messages.
std::string present(const std::string& dir, const std::vector<std::string>& names) {
  std::vector<std::string> found;
  for (const std::string& n : names) {
    std::error_code ec;
    if (fs::exists(fs::path(dir) / n, ec)) found.push_back(n);
  }
  return join_names(found);
}

bool has(const std::string& dir, const char* name) {
  std::error_code ec;
  return fs::exists(fs::path(dir) / name, ec);
}

/// The names of the shard folders of `dir` (a sharded sweep's), for messages.
std::vector<std::string> shard_folders(const std::string& dir) {
  std::vector<std::string> out;
  for (const ShardDir& d : shard_dirs(dir)) out.push_back(fs::path(d.path).filename().string());
  return out;
}

}  // namespace

std::optional<OutputDirContents> output_dir_contents(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return std::nullopt;
  const std::optional<nlohmann::json> manifest = read_manifest((fs::path(dir) / "manifest.json").string());
  if (manifest || has(dir, "runs.csv")) {
    const std::string name = manifest && manifest->contains("name") && (*manifest)["name"].is_string()
                                 ? " '" + (*manifest)["name"].get<std::string>() + "'"
                                 : std::string();
    return OutputDirContents{OutputKind::Sweep, "the results of sweep" + name + " (" +
                                                    present(dir, {"manifest.json", "runs.csv"}) + ")"};
  }
  if (has(dir, "run.csv")) {
    return OutputDirContents{
        OutputKind::Sim,
        "the output of fsweep sim (" + present(dir, {"run.csv", "progress.csv", "trajectory.png"}) + ")"};
  }
  if (has(dir, "queries.csv") || has(dir, "ompl_benchmark.log")) {
    return OutputDirContents{OutputKind::PlanBench,
                             "the output of fsweep plan-bench (" +
                                 present(dir, {"queries.csv", "summary.csv", "ompl_benchmark.log"}) + ")"};
  }
  if (has(dir, "pairs.csv")) {
    return OutputDirContents{OutputKind::PlanCompare,
                             "the output of fsweep plan-compare (" +
                                 present(dir, {"pairs.csv", "summary.csv", "manifest.json"}) + ")"};
  }
  if (has(dir, "compare.csv") || has(dir, "compare.html")) {
    return OutputDirContents{OutputKind::Compare, "the output of fsweep compare (" +
                                                      present(dir, {"compare.csv", "compare.html"}) + ")"};
  }
  if (has(dir, "paired.csv") || has(dir, "paired.json")) {
    return OutputDirContents{OutputKind::Paired, "the output of fsweep paired (" +
                                                     present(dir, {"paired.csv", "paired.json"}) + ")"};
  }
  if (has(dir, "optimum.csv") || has(dir, "route.png")) {
    return OutputDirContents{OutputKind::Optimum, "the output of fsweep optimum (" +
                                                      present(dir, {"optimum.csv", "route.png"}) + ")"};
  }
  if (has(dir, kOptimaFile)) {  // a competitive sweep stopped before its first run ended
    return OutputDirContents{OutputKind::Sweep,
                             std::string("the offline optima of a sweep (") + kOptimaFile + ")"};
  }
  if (const std::vector<std::string> shards = shard_folders(dir); !shards.empty()) {
    return OutputDirContents{OutputKind::Sweep, "the shards of a sweep (" + join_names(shards) + ")"};
  }
  if (has(dir, "progress.png") || has(dir, "metrics.png")) {
    return OutputDirContents{OutputKind::Plots, "the plots of fsweep plot (" +
                                                    present(dir, {"progress.png", "metrics.png"}) + ")"};
  }
  return std::nullopt;
}

void check_output_dir(const std::string& dir, OutputKind kind, const std::string& option) {
  const std::optional<OutputDirContents> held = output_dir_contents(dir);
  if (held && held->kind != kind)
    throw ConfigError(dir, "holds " + held->description + "; choose another " + option);
}

void create_output_dir(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw ConfigError(dir, "cannot create the output directory: " + ec.message());
}

void create_output_dir(const std::string& dir, OutputKind kind, const std::string& option) {
  check_output_dir(dir, kind, option);
  create_output_dir(dir);
}

}  // namespace fsweep
