// The memory limit of `fsweep run`: --max-memory's sizes, and the default read from the cgroup
// files and /proc/meminfo (given here as strings, as a container, a Slurm job or a bare machine
// has them), and the resident memory from /proc/self/statm.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "core/memory_limit.hpp"

namespace fsweep {
namespace test_memory_limit {  // not anonymous: unity builds

constexpr std::uint64_t kMiB = std::uint64_t{1} << 20;
constexpr std::uint64_t kGiB = std::uint64_t{1} << 30;

/// Files by path, read as default_memory_limit() reads them; a path not in the map is missing.
FileText files(std::map<std::string, std::string> contents) {
  return [contents = std::move(contents)](const std::string& path) -> std::optional<std::string> {
    const auto it = contents.find(path);
    if (it == contents.end()) return std::nullopt;
    return it->second;
  };
}

/// /proc/meminfo of a machine of 24 GiB (the kernel writes kB, meaning KiB).
const std::string kMeminfo =
    "MemTotal:       25165824 kB\nMemFree:         1000000 kB\nMemAvailable:   2000000 kB\n";
constexpr std::uint64_t kMachine = std::uint64_t{24} * kGiB;
/// cgroup v1's memory.limit_in_bytes without a limit.
const std::string kV1Unlimited = "9223372036854771712\n";

TEST(MemoryLimit, SizesAreBytesOrNumbersWithBinaryUnits) {
  EXPECT_EQ(parse_memory_size("4G"), 4 * kGiB);
  EXPECT_EQ(parse_memory_size("4g"), 4 * kGiB);
  EXPECT_EQ(parse_memory_size("512M"), 512 * kMiB);
  EXPECT_EQ(parse_memory_size("1.5G"), 3 * kGiB / 2);
  EXPECT_EQ(parse_memory_size("0.3K"), 307U) << "a fraction of a unit is rounded down to whole bytes";
  EXPECT_EQ(parse_memory_size("2T"), 2 * 1024 * kGiB);
  EXPECT_EQ(parse_memory_size("1073741824"), kGiB);
  EXPECT_EQ(parse_memory_size("18446744073709551615"), UINT64_MAX);
}

TEST(MemoryLimit, OtherSizesAreRefused) {
  for (const char* bad : {"", "0", "0G", "0.0001K", "G", "4GB", "4 G", " 4G", "-1G", "+4G", "1.5", "1.G",
                          ".5G", "1.5.2G", "1e9", "four", "18446744073709551616", "16777216T"}) {
    EXPECT_EQ(parse_memory_size(bad), std::nullopt) << "'" << bad << "'";
  }
}

TEST(MemoryLimit, ReadableSizesUseTheLargestUnitLeavingOne) {
  EXPECT_EQ(readable_memory_size(1000), "1,000 B");
  EXPECT_EQ(readable_memory_size(1024), "1 KiB");
  EXPECT_EQ(readable_memory_size(512 * kMiB), "512 MiB");
  EXPECT_EQ(readable_memory_size(3 * kGiB / 2), "1.5 GiB");
}

TEST(MemoryLimit, MemTotalIsReadInKibibytes) {
  EXPECT_EQ(meminfo_total_bytes(kMeminfo), kMachine);
  EXPECT_EQ(meminfo_total_bytes("MemFree: 10 kB\n"), std::nullopt);
  EXPECT_EQ(meminfo_total_bytes("MemTotal: lots\n"), std::nullopt);
  EXPECT_EQ(meminfo_total_bytes(""), std::nullopt);
}

TEST(MemoryLimit, CgroupFilesHoldANumberOrMax) {
  EXPECT_EQ(cgroup_limit_bytes("4294967296\n"), 4 * kGiB);
  EXPECT_EQ(cgroup_limit_bytes("max\n"), std::nullopt);
  EXPECT_EQ(cgroup_limit_bytes(""), std::nullopt);
}

TEST(MemoryLimit, TheProcessCgroupsAreReadFromProcSelfCgroup) {
  const CgroupPaths v2 = parse_proc_cgroup("0::/system.slice/slurmstepd.scope/job_7/step_0/user/task_0\n");
  EXPECT_EQ(v2.v2, "/system.slice/slurmstepd.scope/job_7/step_0/user/task_0");
  EXPECT_EQ(v2.v1_memory, "");
  // A hybrid machine: v1 controllers, one of them memory, beside the v2 hierarchy.
  const CgroupPaths hybrid = parse_proc_cgroup("5:devices:/\n4:memory:/docker/abc\n3:cpu,cpuacct:/\n0::/\n");
  EXPECT_EQ(hybrid.v2, "/");
  EXPECT_EQ(hybrid.v1_memory, "/docker/abc");
  EXPECT_EQ(parse_proc_cgroup("4:cpu,memory:/a:b\n").v1_memory, "/a:b") << "controllers listed together";
  EXPECT_EQ(parse_proc_cgroup("4:memoryx:/a\n").v1_memory, "");
}

TEST(MemoryLimit, WithoutACgroupLimitTheDefaultIsTheMachinesMemory) {
  const std::optional<MemoryLimit> limit =
      default_memory_limit(files({{"/proc/meminfo", kMeminfo},
                                  {"/proc/self/cgroup", "0::/user.slice\n"},
                                  {"/sys/fs/cgroup/user.slice/memory.max", "max\n"}}));
  ASSERT_TRUE(limit);
  EXPECT_EQ(limit->bytes, kMachine);
  EXPECT_EQ(limit->source, "the machine's memory (MemTotal in /proc/meminfo)");
}

TEST(MemoryLimit, AContainersCgroupV2LimitIsTheDefault) {
  // In a container the process's cgroup is the root of its namespace.
  const std::optional<MemoryLimit> limit =
      default_memory_limit(files({{"/proc/meminfo", kMeminfo},
                                  {"/proc/self/cgroup", "0::/\n"},
                                  {"/sys/fs/cgroup/memory.max", "4294967296\n"}}));
  ASSERT_TRUE(limit);
  EXPECT_EQ(limit->bytes, 4 * kGiB);
  EXPECT_EQ(limit->source, "cgroup v2 (/sys/fs/cgroup/memory.max)");
}

TEST(MemoryLimit, TheSmallestLimitOfTheCgroupAndItsAncestorsCounts) {
  // A Slurm job sets the limit on the job's cgroup; the task's own says "max".
  const std::string job = "/sys/fs/cgroup/system.slice/slurmstepd.scope/job_7";
  const std::optional<MemoryLimit> limit = default_memory_limit(
      files({{"/proc/meminfo", kMeminfo},
             {"/proc/self/cgroup", "0::/system.slice/slurmstepd.scope/job_7/step_0/task_0\n"},
             {job + "/step_0/task_0/memory.max", "max\n"},
             {job + "/step_0/memory.max", "8589934592\n"},
             {job + "/memory.max", "2147483648\n"},
             {"/sys/fs/cgroup/system.slice/memory.max", "max\n"}}));
  ASSERT_TRUE(limit);
  EXPECT_EQ(limit->bytes, 2 * kGiB);
  EXPECT_EQ(limit->source, "cgroup v2 (" + job + "/memory.max)");
}

TEST(MemoryLimit, ACgroupLimitAboveTheMachinesMemoryLeavesTheMachines) {
  const std::optional<MemoryLimit> limit =
      default_memory_limit(files({{"/proc/meminfo", kMeminfo},
                                  {"/proc/self/cgroup", "0::/\n"},
                                  {"/sys/fs/cgroup/memory.max", "1099511627776\n"}}));
  ASSERT_TRUE(limit);
  EXPECT_EQ(limit->bytes, kMachine);
}

TEST(MemoryLimit, CgroupV1CountsOnlyBelowTheMachinesMemory) {
  const std::string proc_cgroup = "4:memory:/process_api/974e\n0::/\n";  // as this machine's, hybrid
  const std::optional<MemoryLimit> unlimited = default_memory_limit(
      files({{"/proc/meminfo", kMeminfo},
             {"/proc/self/cgroup", proc_cgroup},
             {"/sys/fs/cgroup/memory/process_api/974e/memory.limit_in_bytes", kV1Unlimited},
             {"/sys/fs/cgroup/memory/memory.limit_in_bytes", kV1Unlimited}}));
  ASSERT_TRUE(unlimited);
  EXPECT_EQ(unlimited->bytes, kMachine);
  const std::optional<MemoryLimit> limited = default_memory_limit(
      files({{"/proc/meminfo", kMeminfo},
             {"/proc/self/cgroup", proc_cgroup},
             {"/sys/fs/cgroup/memory/process_api/974e/memory.limit_in_bytes", "1073741824\n"},
             {"/sys/fs/cgroup/memory/memory.limit_in_bytes", kV1Unlimited}}));
  ASSERT_TRUE(limited);
  EXPECT_EQ(limited->bytes, kGiB);
  EXPECT_EQ(limited->source, "cgroup v1 (/sys/fs/cgroup/memory/process_api/974e/memory.limit_in_bytes)");
}

TEST(MemoryLimit, NothingReadableGivesNoLimit) {
  EXPECT_EQ(default_memory_limit(files({})), std::nullopt);
  // Without /proc/meminfo a v1 number cannot be told from "no limit"; a v2 number still counts.
  EXPECT_EQ(default_memory_limit(files({{"/sys/fs/cgroup/memory/memory.limit_in_bytes", kV1Unlimited}})),
            std::nullopt);
  const std::optional<MemoryLimit> v2 =
      default_memory_limit(files({{"/sys/fs/cgroup/memory.max", "1024\n"}}));
  ASSERT_TRUE(v2);
  EXPECT_EQ(v2->bytes, 1024U);
}

TEST(MemoryLimit, ResidentMemoryIsStatmsSecondFieldInPages) {
  EXPECT_EQ(statm_resident_bytes("765 438 409 5 0 123 0\n", 4096), 438U * 4096U);
  EXPECT_EQ(statm_resident_bytes("765\n", 4096), std::nullopt);
  EXPECT_EQ(statm_resident_bytes("765 x 409\n", 4096), std::nullopt);
  EXPECT_EQ(statm_resident_bytes("765 438 409\n", 0), std::nullopt);
  // This process's, which holds at least this test's code.
  const std::optional<std::uint64_t> mine = resident_memory_bytes();
  ASSERT_TRUE(mine);
  EXPECT_GT(*mine, 0U);
  EXPECT_TRUE(default_memory_limit()) << "this machine has a /proc/meminfo";
}

}  // namespace test_memory_limit
}  // namespace fsweep
