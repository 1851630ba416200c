// `fsweep verify DIR` end to end: a search of mode best writes its certificate, which verifies
// (exit 0); certificates tampered with in each way the check covers fail with the line named
// (exit 1), or are refused as malformed (exit 2). Also what a damaged searches.json does to a
// rerun (which writes it again) and to the report.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli/fsweep_process.hpp"

namespace {

namespace fs = std::filesystem;
using fsweep::testing::read_all;
using fsweep::testing::run_fsweep;
using nlohmann::json;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// The lines of a file, without their newlines.
std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

void write_lines(const std::string& path, const std::vector<std::string>& lines) {
  std::ofstream out(path, std::ios::trunc);
  for (const std::string& l : lines) out << l << '\n';
}

/// Runs the sweep `sweep` (JSON text) from a fresh temporary folder named `name`; returns its
/// output directory, `<folder>/out` (the sweep file is `<folder>/sweep.json`).
std::string run_sweep(const std::string& name, const std::string& sweep) {
  const std::string dir = fsweep::testing::fresh_temp_dir("verify", name);
  fs::create_directories(dir);
  std::ofstream(dir + "/sweep.json") << sweep;
  const auto r = run_fsweep("run " + dir + "/sweep.json --quiet --out " + dir + "/out");
  EXPECT_EQ(r.code, 0) << r.output;
  return dir + "/out";
}

/// A sweep with one search of mode best over 96 vectors of an office map, run once per test
/// program; returns the output directory.
const std::string& searched() {
  static const std::string out = run_sweep("search", R"({"schema_version": 1, "name": "cli_verify",
      "maps": ["office:w=32,h=32,seed=3"],
      "strategies": [{"name": "energy_aware", "search": {"method": "exact", "mode": "best"},
                      "params": {"w1": [0, 1, 2, 3], "w2": [0, 2], "w3": {"range": [0, 5], "step": 1},
                                 "w4": [0, 1]}}],
      "robot": {"sensor": {"range_m": 6}, "energy": "distance", "battery": 300},
      "seed": 5})");
  return out;
}

/// A copy of the searched directory whose certificate `change` edits (its lines, header first).
std::string tampered(const std::string& name, const std::function<void(std::vector<std::string>&)>& change) {
  const std::string dir = fsweep::testing::fresh_temp_dir("verify", name) + "/out";
  fs::create_directories(fs::path(dir).parent_path());
  fs::copy(searched(), dir, fs::copy_options::recursive);
  const std::string path = dir + "/search_certificate_0.jsonl";
  std::vector<std::string> lines = lines_of(path);
  change(lines);
  write_lines(path, lines);
  return dir;
}

/// A copy of the searched directory whose certificate header `change` edits.
std::string with_header(const std::string& name, const std::function<void(json&)>& change) {
  return tampered(name, [&](std::vector<std::string>& lines) {
    json h = json::parse(lines[0]);
    change(h);
    lines[0] = h.dump();
  });
}

/// The first region line (1-based line number) of kind `kind` whose value is not the optimum.
std::size_t first_line(const std::vector<std::string>& lines, const std::string& kind, bool optimal) {
  const double optimum = json::parse(lines.front()).at("optimum").get<double>();
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const json j = json::parse(lines[i]);
    if (j.at("kind") != kind || j.at("value").is_null()) continue;
    if ((j.at("value").get<double>() == optimum) == optimal) return i + 1;
  }
  return 0;
}

TEST(CliVerify, ABestSearchsCertificateVerifies) {
  const std::string& dir = searched();
  ASSERT_TRUE(fs::exists(dir + "/search_certificate_0.jsonl"));
  const json record = json::parse(std::ifstream(dir + "/searches.json"))["searches"][0];
  EXPECT_EQ(record["certificate"]["file"], "search_certificate_0.jsonl");
  const std::vector<std::string> lines = lines_of(dir + "/search_certificate_0.jsonl");
  EXPECT_EQ(record["certificate"]["regions"], lines.size() - 1);
  ASSERT_GT(first_line(lines, "pruned", false), 0U) << "the search pruned nothing: the test checks no bound";
  const auto r = run_fsweep("verify " + dir + " --threads 2");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(has(r.output, "verified")) << r.output;
  EXPECT_TRUE(has(r.output, "sum to the box's, and no vector is in two regions")) << r.output;
}

TEST(CliVerify, ACoverageTargetSearchWithABatteryVerifies) {
  // The bound of the coverage target counts the trips back to the dock (sim/reveal_bound.hpp);
  // the check computes it as the search did.
  const std::string out = run_sweep("target", R"({"schema_version": 1, "name": "cli_verify_target",
    "maps": ["office:w=32,h=32,seed=3"],
    "strategies": [{"name": "energy_aware", "search": {"mode": "best"},
                    "params": {"w1": [0, 1, 2, 3], "w2": [0, 2], "w3": {"range": [0, 5], "step": 1},
                               "w4": [0, 1]}}],
    "robot": {"sensor": {"range_m": 6}, "energy": "distance", "battery": 150},
    "sim": {"stop_at_coverage": 0.7}, "output": {"objective": "distance_to_coverage_target_m"},
    "seed": 5})");
  const json search = json::parse(std::ifstream(out + "/searches.json"))["searches"][0];
  EXPECT_GT(search["certificate"]["pruned_regions"].get<int>(), 0) << search.dump();
  const auto r = run_fsweep("verify " + out);
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(has(r.output, "verified")) << r.output;
}

TEST(CliVerify, AValueBelowTheOptimumFailsNamingItsLine) {
  std::size_t line = 0;
  const std::string dir = tampered("bound", [&](std::vector<std::string>& lines) {
    line = first_line(lines, "pruned", false);
    json j = json::parse(lines[line - 1]);
    j["value"] = json::parse(lines.front()).at("optimum").get<double>() - 1.0;
    lines[line - 1] = j.dump();
  });
  const auto r = run_fsweep("verify " + dir);
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_TRUE(has(r.output, "line " + std::to_string(line) + " (pruned region")) << r.output;
  EXPECT_TRUE(has(r.output, "is not worse than the optimum")) << r.output;
}

/// Raises the value of the first region of `kind` that is not optimal by 0.5 and expects
/// `fsweep verify` to fail naming its line, with `problem` in the message.
void expect_a_raised_value_fails(const std::string& kind, const std::string& problem) {
  std::size_t line = 0;
  const std::string dir = tampered("raised_" + kind, [&](std::vector<std::string>& lines) {
    line = first_line(lines, kind, false);
    json j = json::parse(lines[line - 1]);
    j["value"] = j["value"].get<double>() + 0.5;
    lines[line - 1] = j.dump();
  });
  ASSERT_GT(line, 0U);
  const auto r = run_fsweep("verify " + dir);
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_TRUE(has(r.output, "line " + std::to_string(line) + " (" + kind + " region")) << r.output;
  EXPECT_TRUE(has(r.output, problem)) << r.output;
}

TEST(CliVerify, AnObjectiveItsRunsDoNotGiveFails) {
  expect_a_raised_value_fails("finished", "the objective of its representative's runs is");
}

TEST(CliVerify, ABoundBelowWhatItsRunsGiveStillProvesItsRegion) {
  // As written by a build whose bound was weaker: still above the optimum, so still a proof.
  const std::string dir = tampered("weaker", [&](std::vector<std::string>& lines) {
    const std::size_t line = first_line(lines, "pruned", false);
    const double optimum = json::parse(lines.front()).at("optimum").get<double>();
    json j = json::parse(lines[line - 1]);
    j["value"] = (j["value"].get<double>() + optimum) / 2.0;
    lines[line - 1] = j.dump();
  });
  const auto r = run_fsweep("verify " + dir);
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(has(r.output, "verified")) << r.output;
}

TEST(CliVerify, ABoundAboveWhatItsRunsGiveFails) {
  // A pruned region's bound may be below what its runs give (a weaker bound proves it as well),
  // not above.
  expect_a_raised_value_fails("pruned", "below its value");
}

TEST(CliVerify, ARegionLeftOutOrListedTwiceFails) {
  const std::string gap = tampered("gap", [](std::vector<std::string>& lines) { lines.pop_back(); });
  auto r = run_fsweep("verify " + gap);
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_TRUE(has(r.output, "they do not cover it exactly")) << r.output;
  EXPECT_TRUE(has(r.output, "is in no region")) << r.output;  // the first vector left out, named
  const std::string twice = tampered("twice", [](std::vector<std::string>& lines) {
    lines.push_back(lines[1]);
    lines.erase(lines.begin() + 2);  // the count stays the box's when both lines hold as many vectors
  });
  r = run_fsweep("verify " + twice);
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_TRUE(has(r.output, "overlaps line 2")) << r.output;
}

TEST(CliVerify, TwoBehavioursClaimedAsOneFailAtTheDecisionThatSeparatesThem) {
  // The vectors of a second finished region moved into the first: the cover still holds, but not
  // every vector of the merged region makes the first region's choices.
  std::size_t line = 0;
  const std::string dir = tampered("merged", [&](std::vector<std::string>& lines) {
    const std::size_t a = first_line(lines, "finished", true);
    const std::size_t b = first_line(lines, "finished", false);
    json ja = json::parse(lines[a - 1]);
    const json jb = json::parse(lines[b - 1]);
    for (const json& box : jb.at("boxes")) ja["boxes"].push_back(box);
    lines[a - 1] = ja.dump();
    lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(b - 1));
    line = b < a ? a - 1 : a;
  });
  const auto r = run_fsweep("verify " + dir);
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_TRUE(has(r.output, "line " + std::to_string(line) + " (finished region")) << r.output;
  EXPECT_TRUE(has(r.output, "chooses candidate")) << r.output;
}

TEST(CliVerify, FreshDeletesEveryCertificateBeforeSearchingAgain) {
  const std::string dir = tampered("fresh", [](std::vector<std::string>& /*lines*/) {});
  std::ofstream(dir + "/search_certificate_7.jsonl") << "{}\n";  // one of another sweep's searches
  const std::string sweep = fs::path(searched()).parent_path().string() + "/sweep.json";
  const auto r = run_fsweep("run " + sweep + " --fresh --quiet --out " + dir);
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_FALSE(fs::exists(dir + "/search_certificate_7.jsonl"));
  EXPECT_TRUE(fs::exists(dir + "/search_certificate_0.jsonl"));
}

TEST(CliVerify, AMalformedLineOrAnotherSearchsCertificateIsExit2) {
  const std::string outside = tampered("outside", [](std::vector<std::string>& lines) {
    json j = json::parse(lines[1]);
    j["boxes"][0][0] = 99;
    lines[1] = j.dump();
  });
  auto r = run_fsweep("verify " + outside);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(
      has(r.output, "search_certificate_0.jsonl:2: a box index 99 along w1; allowed: an integer from 0 to 3"))
      << r.output;
  const std::string other = tampered("other", [](std::vector<std::string>& lines) {
    json j = json::parse(lines[0]);
    j["instances"][0]["seed"] = 12345;
    lines[0] = j.dump();
  });
  r = run_fsweep("verify " + other);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(has(r.output, "the certificate is another search's")) << r.output;
}

/// The searched directory copied as `name`, its searches.json's search record edited by `change`.
std::string with_record(const std::string& name, const std::function<void(json&)>& change) {
  const std::string dir = tampered(name, [](std::vector<std::string>& /*lines*/) {});
  json searches = json::parse(std::ifstream(dir + "/searches.json"));
  change(searches["searches"][0]);
  std::ofstream(dir + "/searches.json", std::ios::trunc) << searches.dump();
  return dir;
}

/// `fsweep verify` on `dir` exits `code` with `part` in its output.
void expect_verify(const std::string& dir, int code, const std::string& part) {
  const auto r = run_fsweep("verify " + dir);
  EXPECT_EQ(r.code, code) << r.output;
  EXPECT_TRUE(has(r.output, part)) << "expected '" << part << "' in\n" << r.output;
}

TEST(CliVerify, AKeyALineHoldsTwiceIsExit2) {
  // nlohmann keeps a key's last value, other readers its first: a certificate whose line can be
  // read two ways proves nothing.
  const std::string twice = tampered("twice", [](std::vector<std::string>& lines) {
    const std::size_t close = lines[0].rfind('}');
    lines[0] = lines[0].substr(0, close) + R"(, "direction": "maximize"})";
  });
  auto r = run_fsweep("verify " + twice);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(has(r.output, "search_certificate_0.jsonl:1: /direction: duplicate key 'direction'"))
      << r.output;
  const std::string region = tampered("twice_region", [](std::vector<std::string>& lines) {
    lines[2] = "{\"value\": 0, " + lines[2].substr(1);
  });
  r = run_fsweep("verify " + region);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(has(r.output, "search_certificate_0.jsonl:3: /value: duplicate key 'value'")) << r.output;
  // searches.json, whose counts verify compares, is read the same way.
  const std::string record = tampered("twice_record", [](std::vector<std::string>& /*lines*/) {});
  std::string searches = read_all(record + "/searches.json");
  searches.insert(searches.find("\"behaviours\""), R"("behaviours": 99, )");
  std::ofstream(record + "/searches.json", std::ios::trunc) << searches;
  expect_verify(record, 2, "searches.json: /searches/0/behaviours: duplicate key 'behaviours'");
}

TEST(CliVerify, ACertificateForAnotherBoxObjectiveDirectionOrInstancesIsRefused) {
  // A certificate can prove a false claim only by being another search's: each is refused
  // before its regions are read. Flipping the direction (a lower bound then "proves" a maximum):
  expect_verify(
      with_header("direction", [](json& h) { h["direction"] = "maximize"; }), 2,
      "objective distance_to_final_coverage_m (maximize), where the sweep's (manifest.json) search 0 "
      "has distance_to_final_coverage_m (minimize)");
  // A box cropped around a worse optimum:
  expect_verify(with_header("cropped",
                            [](json& h) {
                              h["values"][0] = json::array({0.0, 1.0});
                              h["vectors"] = h["vectors"].get<int>() / 2;
                            }),
                2, "the box [[0.0,1.0],");
  // Other weight names:
  expect_verify(with_header("weights", [](json& h) { h["weights"][0] = "w9"; }), 2,
                "weights [\"w9\",\"w2\",\"w3\",\"w4\"], where the sweep's (manifest.json) search 0 has "
                "[\"w1\",\"w2\",\"w3\",\"w4\"]");
  // One instance more than the sweep's class has:
  expect_verify(with_header("instances", [](json& h) { h["instances"].push_back(h["instances"][0]); }), 2,
                "instances 2, where the sweep's (manifest.json) search 0 has 1 (maps x repetitions)");
  // Another search's id:
  expect_verify(with_header("search_id", [](json& h) { h["search_id"] = 1; }), 2,
                "search_id 1, where the sweep's (manifest.json) search 0 has 0");
}

TEST(CliVerify, SearchesJsonMustReportTheCertificatesOptimumAndEverySearchOfModeBestOne) {
  expect_verify(with_record("optimum", [](json& record) { record["certificate"]["optimum"] = 1.0; }), 1,
                "searches.json gives the optimum 1.0, the certificate ");
  expect_verify(with_record("regions", [](json& record) { record["certificate"]["regions"] = 3; }), 1,
                "searches.json gives regions 3, the certificate ");
  expect_verify(with_record("no_file", [](json& record) { record["certificate"].erase("file"); }), 1,
                "search 0 (energy_aware, office:w=32,h=32,seed=3): nothing verified: its record in "
                "searches.json names no certificate file");
  expect_verify(with_record("no_record", [](json& record) { record["search_id"] = 5; }), 1,
                "nothing verified: not finished: no record in searches.json");
  expect_verify(
      with_record("elsewhere",
                  [](json& record) { record["certificate"]["file"] = "../out/search_certificate_0.jsonl"; }),
      2,
      "search 0's certificate file '../out/search_certificate_0.jsonl'; allowed: "
      "'search_certificate_0.jsonl' beside it");
}

TEST(CliVerify, AnUnfinishedSearchIsNotVerifiedAndAShardsPartIsRefused) {
  // No searches.json: no search finished (a stopped one keeps its status file).
  const std::string unfinished = tampered("unfinished", [](std::vector<std::string>& /*lines*/) {});
  fs::remove(unfinished + "/searches.json");
  expect_verify(unfinished, 1, "nothing verified: not finished: no record in searches.json");
  // A shard's directory: its certificate is the merge's.
  const std::string sweep = fs::path(searched()).parent_path().string() + "/sweep.json";
  const std::string dir = fsweep::testing::fresh_temp_dir("verify", "sharded") + "/out";
  for (const char* shard : {"0/2", "1/2"}) {
    const auto r = run_fsweep("run " + sweep + " --shard " + shard + " --out " + dir);
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_FALSE(has(r.output, "no behaviour is optimal")) << r.output;  // a shard's files are the merge's
  }
  expect_verify(dir + "/shard-0-of-2", 2,
                "search 0 here is a shard's part (shard {\"count\":2,\"index\":0}): `fsweep merge` on the "
                "shards' parent directory writes its certificate");
  // Merged, the shards' certificate verifies, with the unsharded search's optimum.
  const auto merged = run_fsweep("merge " + dir);
  ASSERT_EQ(merged.code, 0) << merged.output;
  expect_verify(dir, 0, "verified");
  const auto optimum = [](const std::string& out) {
    return json::parse(std::ifstream(out + "/searches.json"))["searches"][0]["certificate"]["optimum"];
  };
  EXPECT_EQ(optimum(dir), optimum(searched()));
  // A merge's searches.json damaged: no journal to write it again from, so not searched again.
  std::ofstream(dir + "/searches.json", std::ios::trunc) << "{\"searches\": [";
  const auto again = run_fsweep("run " + sweep + " --quiet --out " + dir);
  EXPECT_EQ(again.code, 2) << again.output;
  EXPECT_TRUE(has(again.output, "searches.json: not whole, and no search_journal.jsonl beside it"))
      << again.output;
}

TEST(CliVerify, NumbersOfTheWrongTypeOrRangeAreExit2) {
  const auto box_index = [](const json& index) {
    return [index](std::vector<std::string>& lines) {
      json j = json::parse(lines[1]);
      j["boxes"][0][0] = index;
      lines[1] = j.dump();
    };
  };
  // Not read as 0, 1 or 6: refused.
  expect_verify(tampered("float_index", box_index(0.0)), 2,
                ":2: a box index 0.0 along w1; allowed: an integer");
  expect_verify(tampered("bool_index", box_index(true)), 2, ":2: a box index true along w1");
  expect_verify(tampered("wrapping_index", box_index(4294967296LL)), 2,
                ":2: a box index 4294967296 along w1");
  expect_verify(tampered("trace",
                         [](std::vector<std::string>& lines) {
                           const std::size_t line = first_line(lines, "finished", true);
                           json j = json::parse(lines[line - 1]);
                           j["trace"] = "zz" + j["trace"].get<std::string>().substr(2);
                           lines[line - 1] = j.dump();
                         }),
                2, "allowed: 16 hexadecimal digits");
  expect_verify(tampered("choices",
                         [](std::vector<std::string>& lines) {
                           json j = json::parse(lines[1]);
                           j["choices"] = "garbage";
                           lines[1] = j.dump();
                         }),
                2, ":2: choices is not an array");
  // 4 weights of 65,536 values: 2^64 vectors, which a 64-bit count would wrap to 0.
  expect_verify(tampered("huge",
                         [](std::vector<std::string>& lines) {
                           json h = json::parse(lines[0]);
                           std::vector<double> values(65536);
                           for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<double>(i);
                           h["values"] = json::array({values, values, values, values});
                           h["vectors"] = 0;
                           lines = {h.dump()};
                         }),
                2, "a box of more than 2^64 vectors");
}

TEST(CliVerify, ACertificateThatIsNotARegularFileIsRefusedWithoutWaiting) {
  const std::string dir = tampered("fifo", [](std::vector<std::string>& /*lines*/) {});
  fs::remove(dir + "/search_certificate_0.jsonl");
  ASSERT_EQ(::mkfifo((dir + "/search_certificate_0.jsonl").c_str(), 0600), 0);
  expect_verify(dir, 2, "search_certificate_0.jsonl: not a regular file");
}

TEST(CliVerify, ASearchWhoseRunsNeverReachTheirTargetVerifiesWithNoOptimum) {
  // Three steps cannot reveal 99% of the map: no vector has a value, every behaviour is finished
  // without one, and nothing is pruned.
  const std::string out = run_sweep("none", R"({"schema_version": 1, "name": "cli_verify_none",
    "maps": ["office:w=32,h=32,seed=3"],
    "strategies": [{"name": "energy_aware", "search": {"mode": "best"},
                    "params": {"w1": [0, 1], "w2": [0, 1], "w3": [0, 1], "w4": [0, 1]}}],
    "robot": {"sensor": {"range_m": 6}, "energy": "distance", "battery": 300},
    "sim": {"stop_at_coverage": 0.99, "max_steps": 3},
    "output": {"objective": "distance_to_coverage_target_m"}, "seed": 5})");
  const json note = json::parse(std::ifstream(out + "/searches.json"))["searches"][0]["certificate"];
  ASSERT_TRUE(note["optimum"].is_null()) << note.dump();
  expect_verify(out, 0, "optimum none (distance_to_coverage_target_m): no vector's runs have a value");
  // A region claiming a value there fails.
  const std::string valued = out + "_valued";
  fs::copy(out, valued, fs::copy_options::recursive);
  std::vector<std::string> lines = lines_of(valued + "/search_certificate_0.jsonl");
  json j = json::parse(lines[1]);
  j["value"] = 5.0;
  lines[1] = j.dump();
  write_lines(valued + "/search_certificate_0.jsonl", lines);
  expect_verify(valued, 1, "but the optimum is none (no vector has a value)");
}

TEST(CliVerify, ADamagedSearchesJsonIsWrittenAgainByARerunAndNamedByTheReport) {
  // A record whose fields are of other types: the report still writes its page, the search's
  // trajectories labelled without them, and says why the strategies are not compared.
  const std::string damaged = with_record("damaged", [](json& record) {
    record["map_class"] = 7;
    record["strategy_label"] = nullptr;
  });
  auto r = run_fsweep("report " + damaged);
  ASSERT_EQ(r.code, 0) << r.output;
  const std::string page = read_all(damaged + "/report.html");
  EXPECT_TRUE(has(page, "search 0 (? on ?): best behaviour (rank 1")) << page.substr(0, 2000);
  EXPECT_TRUE(has(page, damaged + "/searches.json: not a searches file of fsweep run"))
      << page.substr(0, 2000);
  // Cut short (a full disk, an editor): not "already done"; a rerun reads the journal back and
  // writes it again, with the certificate's counts, and it verifies.
  const std::string cut = tampered("cut_searches", [](std::vector<std::string>& /*lines*/) {});
  const std::string text = read_all(cut + "/searches.json");
  std::ofstream(cut + "/searches.json", std::ios::trunc) << text.substr(0, text.size() / 2);
  r = run_fsweep("run " + fs::path(searched()).parent_path().string() + "/sweep.json --quiet --out " + cut);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(has(r.output, "exact weight search: 1 search, 96 weight vectors")) << r.output;
  EXPECT_EQ(json::parse(read_all(cut + "/searches.json"))["searches"][0]["certificate"],
            json::parse(read_all(searched() + "/searches.json"))["searches"][0]["certificate"]);
  expect_verify(cut, 0, "verified");
}

}  // namespace
