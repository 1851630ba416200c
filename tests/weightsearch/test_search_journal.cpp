// SearchJournal: the lines it appends read back as the same behaviours and subtrees; lines of
// another key are passed over; a damaged line is cut off with everything after it (Repair) or
// refused naming its line with the file left as it was (Refuse); a behaviour that does not fit
// the search's shape is damage.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/config_error.hpp"
#include "core/io_error.hpp"
#include "strategies/strategy.hpp"
#include "weightsearch/search_journal.hpp"
#include "weightsearch/weight_grid.hpp"

namespace fsweep {
namespace {

std::string scratch_journal(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("fsweep_journal_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return (dir / "search_journal.jsonl").string();
}

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A 4-weight grid of 9 values each (blocks cut at 8) and its two shares under two candidates,
/// so that the regions hold whole boxes and partial blocks.
struct Fixture {
  WeightGrid grid{std::vector<std::vector<double>>(4, {0, 1, 2, 3, 4, 5, 6, 7, 8})};
  std::vector<WeightGrid::Share> shares;
  Fixture() {
    Candidates c;
    c.feature_count = 4;
    c.cells.resize(2);
    c.features = {1.0, 2.0, 0.5, 1.0, 2.0, 1.0, 1.0, 0.25};
    shares = grid.split(grid.everything(), c);
  }
  [[nodiscard]] Behaviour behaviour(std::size_t share, std::uint64_t trace) const {
    Behaviour b;
    b.region = shares.at(share).region;
    b.choices = {shares.at(share).candidate};
    b.trace = trace;
    return b;
  }
  [[nodiscard]] JournalShape shape(const std::string& key) const { return {key, &grid, 2, 3}; }
};

using Read = std::vector<JournaledBehaviour>;

std::unordered_map<std::uint64_t, SubtreeTally> read_into(const std::string& path, const JournalShape& shape,
                                                          JournalDamage damage, Read& out) {
  return SearchJournal::read(path, shape, damage, "; the hint",
                             [&](JournaledBehaviour&& b) { out.push_back(std::move(b)); });
}

TEST(SearchJournal, ALineOfAnOlderBuildGetsTheAddedCellEmpty) {
  // Written with 2 cells per row, read with 3 where the middle one was added since: the rows
  // get it empty; without an added cell the line does not fit (damage, refused).
  const Fixture fx;
  const std::string path = scratch_journal("added_cell");
  {
    SearchJournal journal(path);
    journal.append("k", fx.behaviour(0, 5), {{"complete", "12.5"}, {"battery", "3"}});
  }
  JournalShape shape = fx.shape("k");
  shape.added_cell = 1;
  Read read;
  (void)read_into(path, shape, JournalDamage::Refuse, read);
  ASSERT_EQ(read.size(), 1U);
  EXPECT_EQ(read[0].cells,
            (std::vector<std::vector<std::string>>{{"complete", "", "12.5"}, {"battery", "", "3"}}));
  Read refused;
  EXPECT_THROW((void)read_into(path, fx.shape("k"), JournalDamage::Refuse, refused), ConfigError);
}

TEST(SearchJournal, ReadsBackWhatItAppendedForItsKeyOnly) {
  const Fixture fx;
  ASSERT_EQ(fx.shares.size(), 2U);
  const std::string path = scratch_journal("roundtrip");
  const std::vector<std::vector<std::string>> cells{{"complete", "12.5", ""}, {"battery", "", "3"}};
  SubtreeTally tally;
  tally.vectors = 7;
  tally.behaviours = 2;
  tally.pruned_regions = 1;
  tally.pruned_vectors = 3;
  tally.smallest_pruned_bound = 41.25;
  {
    SearchJournal journal(path);
    journal.append("k1", fx.behaviour(0, 0xabcdef0123456789ULL), cells);
    journal.append("k2", fx.behaviour(1, 2), cells);
    journal.append_done("k1", 0xfedcba9876543210ULL, tally);
    journal.append_done("k1", 5, SubtreeTally{});
    journal.append("k1", fx.behaviour(1, 3), cells);
  }
  Read read;
  const auto done = read_into(path, fx.shape("k1"), JournalDamage::Refuse, read);
  ASSERT_EQ(read.size(), 2U);
  for (std::size_t i = 0; i < 2; ++i) {
    const Behaviour& b = read[i].behaviour;
    const WeightRegion& region = fx.shares[i].region;
    EXPECT_EQ(b.vectors, fx.grid.count(region));
    EXPECT_EQ(b.representative, fx.grid.lexmin(region));
    EXPECT_EQ(b.bounds, fx.grid.bounds(region));
    EXPECT_EQ(b.choices, std::vector<int>{fx.shares[i].candidate});
    EXPECT_EQ(read[i].cells, cells);
    std::uint64_t both = 0;  // the same points: each region within the other
    fx.grid.for_each_point(b.region, [&](const auto& at) { both += fx.grid.contains(region, at) ? 1 : 0; });
    EXPECT_EQ(both, fx.grid.count(region));
  }
  EXPECT_EQ(read[0].behaviour.trace, 0xabcdef0123456789ULL);
  EXPECT_EQ(read[1].behaviour.trace, 3U);
  ASSERT_EQ(done.size(), 2U);
  const SubtreeTally& t = done.at(0xfedcba9876543210ULL);
  EXPECT_EQ(t.vectors, 7U);
  EXPECT_EQ(t.behaviours, 2U);
  EXPECT_EQ(t.pruned_regions, 1U);
  EXPECT_EQ(t.pruned_vectors, 3U);
  EXPECT_EQ(t.smallest_pruned_bound, 41.25);
  EXPECT_TRUE(std::isinf(done.at(5).smallest_pruned_bound));
  // A missing journal holds nothing.
  Read none;
  EXPECT_TRUE(read_into(path + ".missing", fx.shape("k1"), JournalDamage::Repair, none).empty());
  EXPECT_TRUE(none.empty());
}

TEST(SearchJournal, ReadCountsTheLinesOfTheCountedKeyWithoutReadingThem) {
  // The same search's key in the format before: its lines of each kind are counted, not read.
  const Fixture fx;
  const std::string path = scratch_journal("counted_key");
  {
    SearchJournal journal(path);
    journal.append("old", fx.behaviour(0, 1), {{"a", "1", ""}, {"b", "", "2"}});
    journal.append_done("old", 9, SubtreeTally{});
    journal.append("new", fx.behaviour(1, 2), {{"a", "1", ""}, {"b", "", "2"}});
    journal.append_done("other", 4, SubtreeTally{});
  }
  JournalShape shape = fx.shape("new");
  shape.counted_key = "old";
  Read read;
  std::size_t counted = 0;
  const auto done = SearchJournal::read(
      path, shape, JournalDamage::Refuse, "", [&](JournaledBehaviour&& b) { read.push_back(std::move(b)); },
      {}, &counted);
  EXPECT_EQ(counted, 2U);
  ASSERT_EQ(read.size(), 1U);
  EXPECT_EQ(read[0].behaviour.trace, 2U);
  EXPECT_TRUE(done.empty());
  // Without a counted key nothing is counted.
  std::size_t none = 0;
  Read again;
  (void)SearchJournal::read(
      path, fx.shape("new"), JournalDamage::Refuse, "",
      [&](JournaledBehaviour&& b) { again.push_back(std::move(b)); }, {}, &none);
  EXPECT_EQ(none, 0U);
}

TEST(SearchJournal, RepairCutsADamagedLineAndEverythingAfterIt) {
  const Fixture fx;
  const std::string path = scratch_journal("repair");
  const std::vector<std::vector<std::string>> cells{{"a", "b", "c"}, {"d", "e", "f"}};
  {
    SearchJournal journal(path);
    journal.append("k", fx.behaviour(0, 1), cells);
  }
  const std::string good = contents(path);
  {
    std::ofstream out(path, std::ios::app | std::ios::binary);
    out << R"({"key": "k", "done": "00"})" << '\n'
        << good << R"({"key":)";  // bad id, a good line, a torn one
  }
  Read read;
  testing::internal::CaptureStderr();
  EXPECT_TRUE(read_into(path, fx.shape("k"), JournalDamage::Repair, read).empty());
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find(path + ":2: bad subtree id"), std::string::npos) << err;
  EXPECT_EQ(read.size(), 1U);
  EXPECT_EQ(contents(path), good);
  // Appending after the repair follows complete lines.
  {
    SearchJournal journal(path);
    journal.append("k", fx.behaviour(1, 2), cells);
  }
  read.clear();
  (void)read_into(path, fx.shape("k"), JournalDamage::Repair, read);
  EXPECT_EQ(read.size(), 2U);
}

TEST(SearchJournal, RefuseNamesTheLineAndLeavesTheFile) {
  const Fixture fx;
  const std::string path = scratch_journal("refuse");
  {
    SearchJournal journal(path);
    journal.append("k", fx.behaviour(0, 1), {{"a", "b", "c"}, {"d", "e", "f"}});
    journal.append("k", fx.behaviour(1, 2), {{"a", "b"}, {"d", "e"}});  // another build's columns
  }
  const std::string before = contents(path);
  Read read;
  try {
    (void)read_into(path, fx.shape("k"), JournalDamage::Refuse, read);
    ADD_FAILURE() << "read a damaged journal";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.where(), path + ":2");
    EXPECT_NE(std::string(e.what()).find("another build's columns; the hint"), std::string::npos) << e.what();
  }
  EXPECT_EQ(contents(path), before);
  // A line of another key is damage too when it does not parse; the shape is checked only for this key's.
  read.clear();
  EXPECT_NO_THROW((void)read_into(path, fx.shape("other"), JournalDamage::Refuse, read));
  EXPECT_TRUE(read.empty());
}

TEST(SearchJournal, ARegionOutsideTheBoxOrTheWrongInstanceCountIsDamage) {
  const Fixture fx;
  const WeightGrid small(std::vector<std::vector<double>>(4, {0, 1, 2}));
  const std::string path = scratch_journal("shape");
  {
    SearchJournal journal(path);
    journal.append("k", fx.behaviour(0, 1), {{"a", "b", "c"}, {"d", "e", "f"}});
  }
  Read read;
  const JournalShape outside{"k", &small, 2, 3};
  EXPECT_THROW((void)read_into(path, outside, JournalDamage::Refuse, read), ConfigError);
  const JournalShape three_instances{"k", &fx.grid, 3, 3};
  EXPECT_THROW((void)read_into(path, three_instances, JournalDamage::Refuse, read), ConfigError);
  EXPECT_TRUE(read.empty());
}

TEST(SearchJournal, AnUnwritablePlaceIsAnErrorNamingTheFileAndTheOsError) {
  const std::string path = "/nonexistent-dir-for-fsweep/search_journal.jsonl";
  try {
    SearchJournal journal(path);
    ADD_FAILURE() << "opened " << path;
  } catch (const IoError& e) {
    EXPECT_EQ(e.path(), path);
    EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fsweep
