#include "sweep/manifest.hpp"

#include <fcntl.h>
#include <oneapi/tbb/version.h>
#include <unistd.h>

#include <ctime>
#include <fstream>
#include <string_view>

#include "core/files.hpp"
#include "core/host_info.hpp"
#include "core/json_text.hpp"
#include "core/random.hpp"
#include "planners/ompl_planner.hpp"
#include "sweep/csv_journal.hpp"
#include "sweep/optimum_table.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_table.hpp"

#ifndef FSWEEP_GIT_REVISION
#define FSWEEP_GIT_REVISION "unknown"
#endif
#ifndef FSWEEP_GIT_DESCRIBE
#define FSWEEP_GIT_DESCRIBE ""
#endif
#ifndef FSWEEP_VERSION
#define FSWEEP_VERSION "unknown"
#endif

namespace fsweep {
inline namespace sweep {
namespace {

std::string compiler() {
#if defined(__clang__)
  return std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  return std::string("gcc ") + __VERSION__;
#else
  return "unknown";
#endif
}

nlohmann::json libraries() {
  return {{"oneTBB", std::to_string(TBB_VERSION_MAJOR) + "." + std::to_string(TBB_VERSION_MINOR) + "." +
                         std::to_string(TBB_VERSION_PATCH)},
          {"nlohmann_json", std::to_string(NLOHMANN_JSON_VERSION_MAJOR) + "." +
                                std::to_string(NLOHMANN_JSON_VERSION_MINOR) + "." +
                                std::to_string(NLOHMANN_JSON_VERSION_PATCH)},
          {"OMPL", ompl_version()}};
}

/// The number at `pointer` of `j`, 0 when absent or not a number (a manifest may be hand-edited).
double number_at(const nlohmann::json& j, const char* pointer) {
  const nlohmann::json::json_pointer p(pointer);
  return j.is_object() && j.contains(p) && j.at(p).is_number() ? j.at(p).get<double>() : 0.0;
}

/// The unsigned integer at `pointer` of `j`, 0 when absent or not one.
std::uint64_t unsigned_at(const nlohmann::json& j, const char* pointer) {
  const nlohmann::json::json_pointer p(pointer);
  if (!j.is_object() || !j.contains(p)) return 0;
  const nlohmann::json& v = j.at(p);
  const bool whole = v.is_number_unsigned() || (v.is_number_integer() && v.get<std::int64_t>() >= 0);
  return whole ? v.get<std::uint64_t>() : 0;
}

}  // namespace

std::string fsweep_version() {
  const std::string describe = FSWEEP_GIT_DESCRIBE;
  return describe.empty() ? std::string(FSWEEP_VERSION) : std::string(FSWEEP_VERSION) + " (" + describe + ")";
}

std::string version_text() {
  std::string text = "fsweep " + fsweep_version() + "\n" + compiler() + "\n";
  const nlohmann::json libs = libraries();
  for (const auto& [name, version] : libs.items()) text += name + " " + version.get<std::string>() + "\n";
  return text;
}

std::string sweep_hash(const nlohmann::json& sweep) { return hex64(fnv1a(sweep.dump())); }

bool same_sweep_but_description(nlohmann::json before, nlohmann::json now) {
  if (!before.is_object() || !now.is_object()) return false;
  before.erase("description");
  now.erase("description");
  return before == now;
}

std::string utc_now_iso8601() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  ::gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof(buf), "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

nlohmann::json session_json(const SweepPlan& plan, const ManifestInfo& info) {
  return {
      {"start_utc", info.start_utc},
      {"end_utc", info.end_utc.empty() ? nlohmann::json(nullptr) : nlohmann::json(info.end_utc)},
      {"status", info.status},
      {"sweep_hash", sweep_hash(plan.source())},
      {"sweep_file", info.sweep_file},
      {"fsweep_version", fsweep_version()},
      {"git_revision", FSWEEP_GIT_REVISION},
      {"host", host_name()},
      {"threads", info.threads},
      {"shard", {{"index", info.shard_index}, {"count", info.shard_count}}},
      {"runs", {{"ran", info.runs.ran}, {"skipped", info.runs.skipped}, {"failed", info.runs.ran_failed}}},
      {"wall_s", info.wall_s},
      {"runs_per_s", info.runs_per_s}};
}

nlohmann::json manifest_json(const SweepPlan& plan, const ManifestInfo& info) {
  nlohmann::json sessions = info.sessions.is_array() ? info.sessions : nlohmann::json::array();
  sessions.push_back(session_json(plan, info));
  std::uint64_t ran = 0;
  double wall_s = 0.0;
  for (const nlohmann::json& s : sessions) {
    ran += unsigned_at(s, "/runs/ran");
    wall_s += number_at(s, "/wall_s");
  }
  const nlohmann::json& first = sessions.front();
  const nlohmann::json::json_pointer start("/start_utc");
  nlohmann::json j;
  j["status"] = info.status;
  j["name"] = plan.name();
  j["sweep_file"] = info.sweep_file;
  j["overrides"] = plan.overrides();
  j["sweep_hash"] = sweep_hash(plan.source());
  j["sweep"] = plan.source();
  j["objective"] = plan.objective();
  j["seed"] = plan.seed();
  j["repetitions"] = plan.repetitions();
  j["warnings"] = sweep_warnings(plan);
  j["maps"] = nlohmann::json::array();
  for (const SweepMap& m : plan.maps()) {
    j["maps"].push_back({{"label", m.label}, {"source", m.map->source}, {"content_hash", m.content_hash}});
    // The resolved `competitive` of each map, in a sweep that has one (older manifests stay as they were).
    if (plan.competitive()) j["maps"].back()["competitive"] = m.competitive;
  }
  if (plan.competitive()) j["optimum_solver"] = optimum_solver_version();
  j["skipped_maps"] = nlohmann::json::array();
  for (const SkippedMap& m : plan.skipped_maps()) {
    j["skipped_maps"].push_back({{"where", m.where}, {"file", m.file}, {"reason", m.reason}});
  }
  j["runs"] = {{"total", info.runs.total},
               {"done", info.runs.done},
               {"skipped", info.runs.skipped},
               {"ran", ran},
               {"failed", info.runs.failed}};
  j["shard"] = {{"index", info.shard_index}, {"count", info.shard_count}};
  j["git_revision"] = FSWEEP_GIT_REVISION;
  j["fsweep_version"] = fsweep_version();
  j["compiler"] = compiler();
  j["libraries"] = libraries();
  j["host"] = host_name();
  j["cpu_model"] = cpu_model();
  j["threads"] = info.threads;
  j["start_utc"] =
      first.contains(start) && first.at(start).is_string() ? first.at(start) : nlohmann::json(info.start_utc);
  j["end_utc"] = info.end_utc.empty() ? nlohmann::json(nullptr) : nlohmann::json(info.end_utc);
  j["wall_s"] = wall_s;
  j["runs_per_s"] = sessions_runs_per_s(sessions);
  j["sessions"] = std::move(sessions);
  return j;
}

nlohmann::json manifest_sessions(const nlohmann::json& manifest) {
  nlohmann::json out = nlohmann::json::array();
  if (!manifest.is_object()) return out;
  if (const auto it = manifest.find("sessions"); it != manifest.end()) {
    if (it->is_array()) {
      for (const nlohmann::json& s : *it) {
        if (s.is_object()) out.push_back(s);
      }
    }
    return out;
  }
  // An fsweep that kept only the last invocation: that one, from the top-level fields.
  nlohmann::json s = nlohmann::json::object();
  for (const char* key : {"start_utc", "end_utc", "status", "sweep_hash", "sweep_file", "fsweep_version",
                          "git_revision", "host", "threads", "shard", "wall_s", "runs_per_s"}) {
    if (const auto it = manifest.find(key); it != manifest.end()) s[key] = *it;
  }
  if (const auto runs = manifest.find("runs"); runs != manifest.end() && runs->is_object()) {
    s["runs"] = nlohmann::json::object();
    for (const char* key : {"ran", "skipped"}) {
      if (const auto it = runs->find(key); it != runs->end()) s["runs"][key] = *it;
    }
  }
  out.push_back(std::move(s));
  return out;
}

double sessions_runs_per_s(const nlohmann::json& sessions) {
  double ran = 0.0;
  double seconds = 0.0;
  if (!sessions.is_array()) return 0.0;
  for (const nlohmann::json& s : sessions) {
    const auto n = static_cast<double>(unsigned_at(s, "/runs/ran"));
    const double per_s = number_at(s, "/runs_per_s");
    if (n > 0.0 && per_s > 0.0) {
      ran += n;
      seconds += n / per_s;
    }
  }
  return seconds > 0.0 ? ran / seconds : 0.0;
}

void write_manifest(const std::string& path, const nlohmann::json& manifest) {
  write_file_atomically(path, manifest.dump(2) + "\n");
}

namespace {

/// Changes the top-level `"status": "running"` of the manifest at `path` (as write_manifest()
/// formats it) to `"status": "failed" ` by overwriting those 9 bytes in place; false when the file
/// or the field is not there or the write fails.
bool mark_running_manifest_failed_in_place(const std::string& path) {
  const std::optional<std::string> text = read_file(path);
  if (!text) return false;
  constexpr std::string_view kKey = "\n  \"status\": ";
  constexpr std::string_view kRunning = "\"running\"";
  constexpr std::string_view kFailed = "\"failed\" ";
  static_assert(kRunning.size() == kFailed.size());
  const std::size_t at = text->find(std::string(kKey) + std::string(kRunning));
  if (at == std::string::npos) return false;
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);  // NOLINT(cppcoreguidelines-pro-type-vararg)
  if (fd < 0) return false;
  const auto offset = static_cast<off_t>(at + kKey.size());
  const bool written =
      ::pwrite(fd, kFailed.data(), kFailed.size(), offset) == static_cast<ssize_t>(kFailed.size());
  return ::close(fd) == 0 && written;
}

}  // namespace

void record_failed_manifest(const std::string& path, const nlohmann::json& manifest) noexcept {
  try {
    write_manifest(path, manifest);
    return;
  } catch (...) {  // NOLINT(bugprone-empty-catch): the status alone, in place, below
  }
  try {
    (void)mark_running_manifest_failed_in_place(path);
  } catch (...) {  // NOLINT(bugprone-empty-catch): the error being reported is the first one
  }
}

std::optional<nlohmann::json> read_manifest(const std::string& path) {
  const std::optional<std::string> text = read_file(path);
  if (!text) return std::nullopt;
  nlohmann::json j = parse_json_or_discard(*text);
  if (j.is_discarded() || !j.is_object() || !j.contains("sweep_hash") || !j["sweep_hash"].is_string()) {
    return std::nullopt;
  }
  return j;
}

namespace {

/// The manifest's "maps" array, or null after adding the reason to `out` (an older fsweep's
/// manifest records no maps).
const nlohmann::json* recorded_maps(const nlohmann::json& manifest, std::vector<std::string>& out) {
  const nlohmann::json* recorded = manifest.contains("maps") ? &manifest["maps"] : nullptr;
  if (recorded == nullptr || !recorded->is_array()) {
    out.emplace_back("manifest.json does not record the maps' content (written by an older fsweep)");
    return nullptr;
  }
  return recorded;
}

}  // namespace

std::vector<std::string> changed_map_contents(const nlohmann::json& manifest, const SweepPlan& plan) {
  std::vector<std::string> out;
  const nlohmann::json* recorded = recorded_maps(manifest, out);
  if (recorded == nullptr) return out;
  for (const nlohmann::json& was : *recorded) {
    if (!was.is_object()) continue;
    const std::string label = was.value("label", std::string());
    const std::string source = was.value("source", std::string());
    const std::string hash = was.value("content_hash", std::string());
    for (const SweepMap& m : plan.maps()) {
      if (m.label != label || m.map->source != source) continue;
      if (m.content_hash != hash) {
        std::string line = "map '" + m.label + "' (" + m.map->source + ") changed: content hash ";
        line.append(hash).append(" then, ").append(m.content_hash).append(" now");
        out.push_back(std::move(line));
      }
      break;
    }
  }
  return out;
}

std::optional<std::string> read_manifest_hash(const std::string& path) {
  const auto j = read_manifest(path);
  if (!j) return std::nullopt;
  return (*j)["sweep_hash"].get<std::string>();
}

std::vector<std::string> changed_maps(const nlohmann::json& manifest, const SweepPlan& plan) {
  std::vector<std::string> out;
  const nlohmann::json* recorded = recorded_maps(manifest, out);
  if (recorded == nullptr) return out;
  const auto& maps = plan.maps();
  for (std::size_t i = 0; i < std::max(maps.size(), recorded->size()); ++i) {
    const nlohmann::json* was = i < recorded->size() ? &(*recorded)[i] : nullptr;
    const std::string was_label = was != nullptr ? was->value("label", std::string()) : std::string();
    const std::string was_hash = was != nullptr ? was->value("content_hash", std::string()) : std::string();
    if (i >= maps.size()) {
      out.push_back("map '" + was_label + "' is no longer in the sweep");
    } else if (was == nullptr) {
      out.push_back("map '" + maps[i].label + "' is new in the sweep");
    } else if (was_label != maps[i].label) {
      out.push_back("map " + std::to_string(i) + " was '" + was_label + "', now '" + maps[i].label + "'");
    } else if (was_hash != maps[i].content_hash) {
      out.push_back("map '" + maps[i].label + "' (" + maps[i].map->source + ") changed: content hash " +
                    was_hash + " then, " + maps[i].content_hash + " now");
    }
  }
  return out;
}

}  // namespace sweep
}  // namespace fsweep
