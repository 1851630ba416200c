// CsvJournal: the append-only CSV files of a sweep, and their repair after a kill.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/config_error.hpp"
#include "sweep/csv_journal.hpp"
#include "sweep/sweep_test_files.hpp"

namespace fsweep {
namespace {

namespace fs = std::filesystem;

std::string temp_file(const std::string& name) {
  return (fs::temp_directory_path() / ("fsweep_journal_" + name + "_" + std::to_string(::getpid()) + ".csv"))
      .string();
}

using testing::read_file;
using testing::write_file;

CsvJournal::RecordFilter fields_are(std::size_t n) {
  return [n](const std::vector<std::string>& f) { return f.size() == n; };
}

TEST(CsvJournal, MissingFileGetsTheHeader) {
  const std::string path = temp_file("missing");
  fs::remove(path);
  {
    CsvJournal j(path, "a,b");
    const CsvRepairStats s = j.repair(fields_are(2));
    EXPECT_EQ(s.kept, 0U);
    j.append("1,2\n");
    EXPECT_EQ(read_file(path), "a,b\n");  // nothing before flush()
    j.flush();
  }
  EXPECT_EQ(read_file(path), "a,b\n1,2\n");
  fs::remove(path);
}

TEST(CsvJournal, TornHeaderIsRewritten) {
  const std::string path = temp_file("torn_header");
  write_file(path, "a,");
  CsvJournal j(path, "a,b");
  EXPECT_EQ(read_file(path), "a,b\n");
  fs::remove(path);
}

TEST(CsvJournal, DifferentHeaderIsRefused) {
  const std::string path = temp_file("header");
  write_file(path, "a,c\n1,2\n");
  try {
    CsvJournal j(path, "a,b");
    FAIL() << "accepted another header";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("--fresh"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read_file(path), "a,c\n1,2\n");  // untouched
  fs::remove(path);
}

TEST(CsvJournal, RepairCutsATornLastRecord) {
  const std::string path = temp_file("torn");
  write_file(path, "a,b\n1,2\n3,4\n5,");
  CsvJournal j(path, "a,b");
  const CsvRepairStats s = j.repair(fields_are(2));
  EXPECT_EQ(s.kept, 2U);
  EXPECT_TRUE(s.torn);
  EXPECT_FALSE(s.rewritten);
  EXPECT_EQ(read_file(path), "a,b\n1,2\n3,4\n");
  fs::remove(path);
}

TEST(CsvJournal, TornInsideAQuotedNewlineIsStillTorn) {
  const std::string path = temp_file("quoted");
  // The last record was cut right after a newline inside its quoted field.
  write_file(path, "a,b\n1,\"x\ny\"\n2,\"line one\n");
  CsvJournal j(path, "a,b");
  std::vector<std::string> second;
  const CsvRepairStats s = j.repair([&](const std::vector<std::string>& f) {
    second = f;
    return f.size() == 2;
  });
  EXPECT_EQ(s.kept, 1U);
  EXPECT_TRUE(s.torn);
  EXPECT_EQ(second.at(1), "x\ny");
  EXPECT_EQ(read_file(path), "a,b\n1,\"x\ny\"\n");
  fs::remove(path);
}

TEST(CsvJournal, RejectedTailIsTruncated) {
  const std::string path = temp_file("tail");
  write_file(path, "a,b\n1,2\n3,4\n5,6\n");
  CsvJournal j(path, "a,b");
  const CsvRepairStats s = j.repair([](const std::vector<std::string>& f) { return f[0] == "1"; });
  EXPECT_EQ(s.kept, 1U);
  EXPECT_EQ(s.dropped, 2U);
  EXPECT_FALSE(s.rewritten);
  EXPECT_EQ(read_file(path), "a,b\n1,2\n");
  fs::remove(path);
}

TEST(CsvJournal, RejectedRecordBeforeAKeptOneRewrites) {
  const std::string path = temp_file("middle");
  write_file(path, "a,b\n1,2\nbad\n3,4\n5");
  CsvJournal j(path, "a,b");
  const CsvRepairStats s = j.repair(fields_are(2));
  EXPECT_EQ(s.kept, 2U);
  EXPECT_EQ(s.dropped, 1U);
  EXPECT_TRUE(s.torn);
  EXPECT_TRUE(s.rewritten);
  EXPECT_EQ(read_file(path), "a,b\n1,2\n3,4\n");
  j.append("7,8\n");
  j.flush();
  EXPECT_EQ(read_file(path), "a,b\n1,2\n3,4\n7,8\n");
  fs::remove(path);
}

TEST(CsvJournal, SplitsQuotedFields) {
  EXPECT_EQ(split_csv_line("a,\"b,c\",\"say \"\"hi\"\"\","),
            (std::vector<std::string>{"a", "b,c", "say \"hi\"", ""}));
}

}  // namespace
}  // namespace fsweep
