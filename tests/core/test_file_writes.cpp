// The two writers of result files when the machine refuses a write: AppendFile cuts off the
// part of an append that was written, ReplacingFile leaves the old file and no temp file, and
// both throw IoError naming the file and the OS error. The refusals are a file size limit
// (RLIMIT_FSIZE lowered for this process, as `ulimit -f` does, with SIGXFSZ ignored as fsweep
// ignores it) and /dev/full, which refuses every write as a full disk does.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "core/append_file.hpp"
#include "core/file_size_limit_for_tests.hpp"
#include "core/files.hpp"
#include "core/io_error.hpp"
#include "core/replacing_file.hpp"

namespace fsweep {
namespace test_file_writes {  // not anonymous: unity builds

namespace fs = std::filesystem;
using test_support::FileSizeLimit;

std::string temp_dir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("fsweep_file_writes_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(AppendFile, AnAppendPastTheFileSizeLimitIsCutOffAndNamesTheFileAndTheOsError) {
  const std::string dir = temp_dir("append");
  const std::string path = dir + "/journal.csv";
  const std::string line(60, 'a');
  AppendFile file(path);
  std::optional<IoError> error;
  {  // nothing printed under the limit: the test's output may be a file
    const FileSizeLimit limit(100);
    ASSERT_TRUE(limit.ok());
    file.write(line + '\n');
    // The second line's first 39 bytes fit under the limit: write(2) stores them, then fails.
    try {
      file.write(line + '\n');
    } catch (const IoError& e) {
      error = e;
    }
  }
  ASSERT_TRUE(error.has_value()) << "wrote past the file size limit";
  EXPECT_EQ(error->path(), path);
  EXPECT_EQ(error->os_error(), EFBIG);
  EXPECT_EQ(std::string(error->what()), path + ": write failed: File too large");
  EXPECT_EQ(read_all(path), line + '\n');  // the torn line was cut off
  file.write("b\n");                       // the file goes on after it, once there is room
  EXPECT_EQ(read_all(path), line + "\nb\n");
  fs::remove_all(dir);
}

TEST(AppendFile, AFullDiskNamesTheFileAndTheOsError) {
  AppendFile file("/dev/full");
  try {
    file.write("a line\n");
    ADD_FAILURE() << "/dev/full took a write";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()), "/dev/full: write failed: No space left on device");
  }
}

TEST(ReplacingFile, AFileTooLargeLeavesTheOldFileAndNoTempFile) {
  const std::string dir = temp_dir("replace");
  const std::string path = dir + "/summary.csv";
  write_file_atomically(path, "old\n");
  std::optional<IoError> error;
  {  // nothing printed under the limit: the test's output may be a file
    const FileSizeLimit limit(100);
    ASSERT_TRUE(limit.ok());
    try {
      write_file_atomically(path, std::string(200, 'n'));
    } catch (const IoError& e) {
      error = e;
    }
  }
  ASSERT_TRUE(error.has_value()) << "wrote past the file size limit";
  EXPECT_EQ(std::string(error->what()), path + ": write failed: File too large");
  EXPECT_EQ(read_all(path), "old\n");
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    EXPECT_EQ(e.path().filename(), "summary.csv") << "left behind: " << e.path();
  }
  fs::remove_all(dir);
}

TEST(ReplacingFile, NothingReplacesTheOldFileBeforeCommitNorWithoutIt) {
  const std::string dir = temp_dir("uncommitted");
  const std::string path = dir + "/certificate.jsonl";
  write_file_atomically(path, "old\n");
  {
    ReplacingFile file(path);
    file.write("new\n");
    EXPECT_EQ(read_all(path), "old\n");
  }  // not committed: dropped
  EXPECT_EQ(read_all(path), "old\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  ReplacingFile file(path);
  file.write("new\n");
  file.commit();
  EXPECT_EQ(read_all(path), "new\n");
  fs::remove_all(dir);
}

}  // namespace test_file_writes
}  // namespace fsweep
