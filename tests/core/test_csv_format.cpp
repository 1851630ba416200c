// Numbers as CSV cells, quoting and records (csv_format.hpp), read back by csv_reader.hpp.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "core/csv_format.hpp"
#include "core/csv_reader.hpp"

namespace fsweep {
namespace {

TEST(FormatNumber, ShortestTextThatReadsBack) {
  EXPECT_EQ(format_number(0.1), "0.1");
  EXPECT_EQ(format_number(2.0), "2");
  EXPECT_EQ(format_number(-1.5), "-1.5");
  EXPECT_EQ(format_number(1e-300), "1e-300");
  for (const double v : {0.1 + 0.2, 1.0 / 3.0, 123456.789, 6.02214076e23}) {
    EXPECT_EQ(*parse_number(format_number(v)), v) << format_number(v);
  }
}

TEST(FormatNumber, NonFiniteValuesAreWords) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(format_number(inf), "inf");
  EXPECT_EQ(format_number(-inf), "-inf");
  EXPECT_EQ(format_number(std::nan("")), "nan");
}

TEST(NumberCell, NanIsAnEmptyCell) {
  EXPECT_EQ(number_cell(std::nan("")), "");
  EXPECT_EQ(number_cell(2.5), "2.5");
  EXPECT_EQ(number_cell(std::numeric_limits<double>::infinity()), "inf");
}

TEST(CsvField, QuotesOnlyWhenNeeded) {
  EXPECT_EQ(csv_field("plain text"), "plain text");
  EXPECT_EQ(csv_field("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csv_field("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(csv_field("cr\r"), "\"cr\r\"");
}

TEST(CsvRecord, ReadsBackAsTheSameFields) {
  const std::vector<std::string> fields{"", "a,b", "\"q\"", "x\ny", "3.5"};
  EXPECT_EQ(csv_record(fields), ",\"a,b\",\"\"\"q\"\"\",\"x\ny\",3.5");
  EXPECT_EQ(csv_record({}), "");
  const auto path = std::filesystem::temp_directory_path() /
                    ("fsweep_csv_format_record_" + std::to_string(getpid()) + ".csv");
  {
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    f << csv_record({"c0", "c1", "c2", "c3", "c4"}) << '\n' << csv_record(fields) << '\n';
  }
  CsvReader in(path.string());
  ASSERT_TRUE(in.next());
  EXPECT_EQ(in.fields(), fields);
  EXPECT_FALSE(in.next());
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace fsweep
