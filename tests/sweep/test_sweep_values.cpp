// Sweep values: a scalar, a list, or {"range": [lo, hi], "step": s} (sweep_plan.hpp).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sweep/sweep_plan.hpp"

namespace fsweep {
namespace {

using nlohmann::json;

struct Expanded {
  std::vector<json> values;
  std::vector<std::string> problems;
};

Expanded expand(const json& v) {
  Expanded e;
  e.values = expand_values(v, "/x", e.problems);
  return e;
}

bool mentions(const std::vector<std::string>& problems, const std::string& text) {
  for (const auto& p : problems) {
    if (p.find(text) != std::string::npos) return true;
  }
  return false;
}

TEST(SweepValues, ScalarIsOneValue) {
  const Expanded e = expand(json(7));
  ASSERT_EQ(e.values.size(), 1U);
  EXPECT_EQ(e.values[0], json(7));
  EXPECT_TRUE(e.problems.empty());
}

TEST(SweepValues, ObjectWithoutRangeIsOneValue) {
  const json v = {{"preset", "mei2006"}, {"per_stop", 0.7}};
  const Expanded e = expand(v);
  ASSERT_EQ(e.values.size(), 1U);
  EXPECT_EQ(e.values[0], v);
}

TEST(SweepValues, ListKeepsItsOrder) {
  const Expanded e = expand(json{3, 1, 2});
  EXPECT_EQ(e.values, (std::vector<json>{3, 1, 2}));
  EXPECT_TRUE(e.problems.empty());
}

TEST(SweepValues, EmptyListIsAProblem) {
  const Expanded e = expand(json::array());
  EXPECT_TRUE(e.values.empty());
  ASSERT_EQ(e.problems.size(), 1U);
  EXPECT_EQ(e.problems[0].rfind("/x: empty list", 0), 0U) << e.problems[0];
}

TEST(SweepValues, RepeatedListValueIsAProblemAtItsIndex) {
  const Expanded e = expand(json{1, 2, 1.0});  // 1 and 1.0 are the same number
  EXPECT_TRUE(e.values.empty());
  EXPECT_TRUE(mentions(e.problems, "/x/2: value 1.0 repeats")) << e.problems.at(0);
}

TEST(SweepValues, IntegerRangeIncludesEndAndStaysInteger) {
  const Expanded e = expand(json{{"range", {0, 250}}, {"step", 1}});
  ASSERT_EQ(e.values.size(), 251U);
  EXPECT_TRUE(e.values.front().is_number_integer());
  EXPECT_TRUE(e.values.back().is_number_integer());
  EXPECT_EQ(e.values.back(), json(250));
  EXPECT_EQ(e.values[17].dump(), "17");
}

TEST(SweepValues, IntegerRangeStopsAtTheLastGridPointBelowHi) {
  const Expanded e = expand(json{{"range", {0, 10}}, {"step", 3}});
  EXPECT_EQ(e.values, (std::vector<json>{0, 3, 6, 9}));
}

TEST(SweepValues, NegativeIntegerRange) {
  const Expanded e = expand(json{{"range", {-4, 2}}, {"step", 2}});
  EXPECT_EQ(e.values, (std::vector<json>{-4, -2, 0, 2}));
  EXPECT_EQ(e.values[0].dump(), "-4");
}

TEST(SweepValues, DegenerateRangeIsOneValue) {
  const Expanded e = expand(json{{"range", {5, 5}}, {"step", 1}});
  EXPECT_EQ(e.values, (std::vector<json>{5}));
}

TEST(SweepValues, FloatStepIsRoundedToTheDecimalsWritten) {
  const Expanded e = expand(json{{"range", {0, 1}}, {"step", 0.1}});
  ASSERT_EQ(e.values.size(), 11U);            // 1.0 is included although 10 * 0.1 != 1.0 in binary
  EXPECT_EQ(e.values[3].get<double>(), 0.3);  // not 0.30000000000000004
  EXPECT_EQ(e.values[3].dump(), "0.3");
  EXPECT_EQ(e.values[7].dump(), "0.7");
  EXPECT_EQ(e.values.back().get<double>(), 1.0);
  EXPECT_TRUE(e.values.front().is_number_float());
}

TEST(SweepValues, FloatRangeWithFloatEnds) {
  const Expanded e = expand(json{{"range", {0.1, 0.7}}, {"step", 0.2}});
  ASSERT_EQ(e.values.size(), 4U);
  EXPECT_EQ(e.values[1].get<double>(), 0.3);
  EXPECT_EQ(e.values[3].get<double>(), 0.7);
}

TEST(SweepValues, FloatStepOnIntegerEndsGivesFloats) {
  const Expanded e = expand(json{{"range", {0, 250}}, {"step", 62.5}});
  EXPECT_EQ(e.values, (std::vector<json>{0.0, 62.5, 125.0, 187.5, 250.0}));
  EXPECT_TRUE(e.values[2].is_number_float());
}

TEST(SweepValues, BadStepIsAProblem) {
  for (const json& step : {json(0), json(-1), json("1"), json(-0.5)}) {
    const Expanded e = expand(json{{"range", {0, 10}}, {"step", step}});
    EXPECT_TRUE(e.values.empty());
    EXPECT_TRUE(mentions(e.problems, "/x/step: value " + step.dump())) << step.dump();
    EXPECT_TRUE(mentions(e.problems, "allowed: a number > 0")) << step.dump();
  }
}

TEST(SweepValues, MissingStepIsAProblem) {
  const Expanded e = expand(json{{"range", {0, 10}}});
  EXPECT_TRUE(e.values.empty());
  EXPECT_TRUE(mentions(e.problems, "/x: a range needs \"step\""));
}

TEST(SweepValues, LoAboveHiIsAProblem) {
  const Expanded e = expand(json{{"range", {10, 0}}, {"step", 1}});
  EXPECT_TRUE(e.values.empty());
  EXPECT_TRUE(mentions(e.problems, "/x/range: lo 10 > hi 0; allowed: lo <= hi"));
}

TEST(SweepValues, MalformedRangeAndUnknownKeyAreProblems) {
  const Expanded e = expand(json{{"range", {0}}, {"step", 1}, {"stop", 3}});
  EXPECT_TRUE(e.values.empty());
  EXPECT_TRUE(mentions(e.problems, "/x/range: expected [lo, hi]"));
  EXPECT_TRUE(mentions(e.problems, "/x/stop: unknown key 'stop' in a range; allowed: range, step"));
}

TEST(SweepValues, TooManyValuesIsAProblemNotATruncation) {
  const Expanded e = expand(json{{"range", {0, 10'000'000}}, {"step", 1}});
  EXPECT_TRUE(e.values.empty());
  EXPECT_TRUE(mentions(e.problems, "10,000,001 values; allowed: at most 1,000,000"));
}

}  // namespace
}  // namespace fsweep
