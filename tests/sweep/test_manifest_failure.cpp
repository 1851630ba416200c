// record_failed_manifest(): a session stopped by a full disk or a file size limit still leaves
// its manifest saying "failed", even when the machine refuses the new manifest too (it then
// changes the status of the one on disk in place, in the same bytes). The refusal here is a
// file size limit just above the size of the manifest on disk, so the new manifest (longer: it
// has an end time) cannot be written beside it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/file_size_limit_for_tests.hpp"
#include "core/files.hpp"
#include "sweep/manifest.hpp"

namespace fsweep {
namespace test_manifest_failure {  // not anonymous: unity builds

namespace fs = std::filesystem;
using json = nlohmann::json;

std::string fresh_dir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("fsweep_manifest_failure_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

json running_manifest() {
  return json{{"sweep_hash", "0123abcd"},
              {"status", "running"},
              {"start_utc", "2026-01-01T00:00:00Z"},
              {"sessions", json::array({json{{"status", "running"}, {"runs", 3}}})}};
}

json failed_manifest() {
  json m = running_manifest();
  m["status"] = "failed";
  m["end_utc"] = "2026-01-01T00:10:00Z";
  return m;
}

TEST(ManifestFailure, AFailureIsRecordedByANewManifestWhenTheMachineAllowsIt) {
  const std::string path = fresh_dir("allowed") + "/manifest.json";
  write_manifest(path, running_manifest());
  record_failed_manifest(path, failed_manifest());
  EXPECT_EQ(json::parse(core::read_file(path).value()), failed_manifest());
}

TEST(ManifestFailure, AManifestThatCannotBeReplacedHasItsStatusChangedInPlace) {
  const std::string dir = fresh_dir("refused");
  const std::string path = dir + "/manifest.json";
  write_manifest(path, running_manifest());
  const std::string before = core::read_file(path).value();
  {
    const test_support::FileSizeLimit limit(before.size() + 4);
    ASSERT_TRUE(limit.ok());
    record_failed_manifest(path, failed_manifest());  // never throws
  }
  const std::string after = core::read_file(path).value();
  ASSERT_EQ(after.size(), before.size());
  const json m = json::parse(after);
  EXPECT_EQ(m["status"], "failed");
  EXPECT_FALSE(m.contains("end_utc"));               // the new manifest was not written
  EXPECT_EQ(m["sessions"][0]["status"], "running");  // only the top-level status changes
  EXPECT_EQ(m["start_utc"], "2026-01-01T00:00:00Z");
  // No temp file of the refused replacement is left beside it.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 1);
}

TEST(ManifestFailure, AManifestThatIsNotRunningOrMissingIsLeftAlone) {
  const std::string dir = fresh_dir("alone");
  const std::string path = dir + "/manifest.json";
  json complete = running_manifest();
  complete["status"] = "complete";
  write_manifest(path, complete);
  const std::string before = core::read_file(path).value();
  {
    const test_support::FileSizeLimit limit(before.size() + 4);
    ASSERT_TRUE(limit.ok());
    record_failed_manifest(path, failed_manifest());
    record_failed_manifest(dir + "/missing.json", failed_manifest());
  }
  EXPECT_EQ(core::read_file(path).value(), before);
  EXPECT_FALSE(fs::exists(dir + "/missing.json"));
}

}  // namespace test_manifest_failure
}  // namespace fsweep
