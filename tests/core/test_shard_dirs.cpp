#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/shard_dirs.hpp"
#include "sweep/sweep_test_files.hpp"

namespace fsweep {
namespace {

namespace fs = std::filesystem;

TEST(ShardDirs, AreTheFoldersNamedAsShardsInSplitThenIndexOrder) {
  const std::string dir = testing::fresh_dir("core", "shard_names");
  for (const char* name : {"shard-1-of-2", "shard-0-of-2", "shard-0-of-1", "shard-x-of-2", "shard-1-of-",
                           "shard-99999999999999999999999-of-2", "other"}) {
    fs::create_directories(dir + "/" + name);
  }
  testing::write_file(dir + "/shard-3-of-4", "a file, not a folder");
  const std::vector<ShardDir> found = shard_dirs(dir);
  ASSERT_EQ(found.size(), 3U);
  EXPECT_EQ(found[0].path, dir + "/" + shard_dir_name(0, 1));
  EXPECT_EQ(found[1].path, dir + "/" + shard_dir_name(0, 2));
  EXPECT_EQ(found[2].path, dir + "/shard-1-of-2");
  EXPECT_EQ(found[2].index, 1U);
  EXPECT_EQ(found[2].count, 2U);
  EXPECT_TRUE(shard_dirs(dir + "/missing").empty());
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fsweep
