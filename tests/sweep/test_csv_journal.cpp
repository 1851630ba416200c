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
  return [n](const std::vector<std::string>& f) {
    return f.size() == n ? std::string() : std::to_string(f.size()) + " fields";
  };
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
    return f.size() == 2 ? "" : "not 2 fields";
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
  const CsvRepairStats s =
      j.repair([](const std::vector<std::string>& f) { return f[0] == "1" ? "" : "not run 1"; });
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

TEST(CsvJournal, ACheckThrowingBeforeTheCutLeavesTheFileAsItWas) {
  const std::string path = temp_file("before_changes");
  const std::string text = "a,b\n1,2\nbad\n3,4\n5";  // a dropped line and a torn tail
  write_file(path, text);
  CsvJournal j(path, "a,b");
  std::size_t rows_seen = 0;
  std::size_t rows_seen_at_check = 0;
  const auto keep = [&](const std::vector<std::string>& f) -> std::string {
    ++rows_seen;
    return f.size() == 2 ? "" : "wrong field count";
  };
  EXPECT_THROW((void)j.repair(keep,
                              [&] {
                                rows_seen_at_check = rows_seen;
                                throw ConfigError(path, "refused");
                              }),
               ConfigError);
  EXPECT_EQ(rows_seen_at_check, 3U);  // after the whole scan (the torn tail is not a row)
  EXPECT_EQ(read_file(path), text);
  fs::remove(path);
}

TEST(CsvJournal, RepairNamesEveryDroppedLineAndWhy) {
  const std::string path = temp_file("reasons");
  // Line 3 is garbage; 4 and 5 are one reason (merged); 6 has a stray quote, which must not
  // swallow line 7; 8 has a bare carriage return; 9 has text after a closing quote; 11 is torn.
  write_file(path, "a,b\n1,2\ngarbage\nx\ny\n3,4\"\n5,6\n7,\r8\n\"9\"z,1\n10,11\n12,1");
  CsvJournal j(path, "a,b");
  const CsvRepairStats s = j.repair(fields_are(2));
  EXPECT_EQ(s.kept, 3U);
  EXPECT_EQ(s.dropped, 6U);
  ASSERT_EQ(s.dropped_lines.size(), 5U);
  EXPECT_EQ(s.dropped_lines[0].describe("f.csv"), "f.csv:3-5: 1 fields");
  EXPECT_EQ(s.dropped_lines[1].describe("f.csv"),
            "f.csv:6: field 2 has a quote (\") inside it but does not start with one");
  EXPECT_EQ(s.dropped_lines[2].describe("f.csv"),
            "f.csv:8: a carriage return (\\r) inside the line, where only a line feed (\\n) ends a line");
  EXPECT_EQ(
      s.dropped_lines[3].describe("f.csv"),
      "f.csv:9: field 1 has 'z' after its closing quote, where a comma or the end of the line was expected");
  EXPECT_EQ(s.dropped_lines[4].describe("f.csv"),
            "f.csv:11: the last line is cut short (no final newline: a write torn by a kill)");
  EXPECT_EQ(read_file(path), "a,b\n1,2\n5,6\n10,11\n");
  fs::remove(path);
}

TEST(CsvJournal, ADamagedRowsUnclosedQuoteCostsOnlyItsOwnLine) {
  const std::string path = temp_file("unclosed");
  // Line 3's quote is closed on line 5 ("7,"), where 'q' follows it: one malformed record over
  // lines 3-5, of which only line 3 is damaged.
  write_file(path, "a,b\n1,2\n3,\"x\n5,6\n7,\"q\"\n9,10\n");
  CsvJournal j(path, "a,b");
  const CsvRepairStats s = j.repair(fields_are(2));
  EXPECT_EQ(s.kept, 4U);
  EXPECT_EQ(s.dropped, 1U);
  ASSERT_EQ(s.dropped_lines.size(), 1U);
  EXPECT_EQ(s.dropped_lines[0].describe("f.csv"),
            "f.csv:3: field 2 has 'q' after its closing quote, where a comma or the end of the line was "
            "expected (read as one record with the lines up to 5, which are read again on their own)");
  EXPECT_EQ(read_file(path), "a,b\n1,2\n5,6\n7,\"q\"\n9,10\n");

  // A quote never closed: the lines after it are not a torn tail.
  write_file(path, "a,b\n1,2\n3,\"x\n5,6\n7,8\n");
  const CsvRepairStats t = j.repair(fields_are(2));
  EXPECT_EQ(t.kept, 3U);
  EXPECT_TRUE(t.torn);
  ASSERT_EQ(t.dropped_lines.size(), 1U);
  EXPECT_EQ(t.dropped_lines[0].first_line, 3U);
  EXPECT_EQ(t.dropped_lines[0].last_line, 3U);
  EXPECT_EQ(read_file(path), "a,b\n1,2\n5,6\n7,8\n");
  fs::remove(path);
}

TEST(CsvJournal, RewriteInOrderSortsStably) {
  const std::string path = temp_file("order");
  write_file(path, "i,v\n0,a\n4,b\n2,c\n4,d\nx,y\n1,e\n");
  CsvJournal j(path, "i,v");
  (void)j.repair(fields_are(2));
  j.append("3,f\n");
  j.flush();  // the rewrite must reopen the file it appends to
  j.rewrite_in_order(0);
  EXPECT_EQ(read_file(path), "i,v\n0,a\n1,e\n2,c\n3,f\n4,b\n4,d\nx,y\n");  // no number: last
  j.append("5,g\n");
  j.flush();
  EXPECT_EQ(read_file(path), "i,v\n0,a\n1,e\n2,c\n3,f\n4,b\n4,d\nx,y\n5,g\n");
  fs::remove(path);
}

TEST(CsvJournal, RewriteInOrderRenumbersDropsAndChangesTheHeader) {
  const std::string path = temp_file("renumber");
  write_file(path, "i,v\n0,a\n1,\"b,1\"\n2,c\n3,d\n");
  CsvJournal j(path, "i,v");
  (void)j.repair(fields_are(2));
  // Run i becomes run 10 - 3 i with a new column; run 2 is left out.
  CsvJournal::Rewrite rewrite;
  rewrite.place = [](const std::vector<std::string>& f) -> std::optional<std::uint64_t> {
    if (f[0] == "2") return std::nullopt;
    return 10 - 3 * std::stoi(f[0]);
  };
  rewrite.fill = [](std::uint64_t index, std::vector<std::string>& f) {
    f = {std::to_string(index), "new", f[1]};
  };
  rewrite.header = "i,w,v";
  j.rewrite_in_order(0, rewrite);
  EXPECT_EQ(read_file(path), "i,w,v\n1,new,d\n7,new,\"b,1\"\n10,new,a\n");
  j.append("11,new,e\n");
  j.flush();
  EXPECT_EQ(read_file(path), "i,w,v\n1,new,d\n7,new,\"b,1\"\n10,new,a\n11,new,e\n");
  fs::remove(path);
}

TEST(CsvJournal, SplitsQuotedFields) {
  EXPECT_EQ(split_csv_line("a,\"b,c\",\"say \"\"hi\"\"\","),
            (std::vector<std::string>{"a", "b,c", "say \"hi\"", ""}));
}

}  // namespace
}  // namespace fsweep
