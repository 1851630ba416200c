// JSON text helpers: nesting bounded before parsing (parse_json_or_discard, parse_json_bounded).
#include <gtest/gtest.h>

#include <string>

#include "core/config_error.hpp"
#include "core/json_text.hpp"

namespace fsweep {
namespace {

std::string nested(int levels) { return std::string(levels, '[') + std::string(levels, ']'); }

TEST(JsonText, NestingUpToTheLimitParsesDeeperIsRefusedBeforeParsing) {
  EXPECT_EQ(parse_json_or_discard(nested(kMaxJsonNesting)).dump(),
            nested(kMaxJsonNesting));  // copied and dumped: a walk of every level
  EXPECT_TRUE(parse_json_or_discard(nested(kMaxJsonNesting + 1)).is_discarded());
  // 200,000 levels: nlohmann parses them, but a copy recursed past the stack.
  EXPECT_TRUE(parse_json_or_discard(nested(200'000)).is_discarded());
  EXPECT_TRUE(parse_json_or_discard("{\"a\": ").is_discarded());
  // Brackets inside strings do not nest.
  EXPECT_EQ(parse_json_or_discard("{\"a\": \"" + nested(1000) + "\"}")["a"].get<std::string>().size(), 2000U);
}

TEST(JsonText, BoundedParseNamesThePlaceOfTheTooDeepOpening) {
  EXPECT_EQ(parse_json_bounded("{\"k\": 1}", "f.json")["k"], 1);
  try {
    (void)parse_json_bounded("{\n  \"x\": " + nested(kMaxJsonNesting + 5) + "}", "f.json");
    FAIL() << "too deep JSON parsed";
  } catch (const ConfigError& e) {
    // The object is level 1: the 128th '[' opens level 129, at line 2, column 8 + 127.
    EXPECT_EQ(std::string(e.what()),
              "f.json:2:135: JSON nested deeper than 128 levels (arrays and objects); "
              "allowed: at most 128");
  }
  EXPECT_THROW((void)parse_json_bounded("{", "f.json"), nlohmann::json::parse_error);
}

TEST(JsonText, NonFiniteWordsOutsideStringsBecomeNull) {
  // As Google Benchmark writes a counter's coefficient of variation when its mean is 0.
  const std::string text =
      R"({"exact": NaN, "gap": -Infinity, "n": -NaN, "up": Infinity, "name": "NaN Infinity", "x": [NaN]})";
  EXPECT_EQ(null_non_finite_words(text),
            R"({"exact": null, "gap": null, "n": null, "up": null, "name": "NaN Infinity", "x": [null]})");
  EXPECT_TRUE(nlohmann::json::parse(null_non_finite_words(text)).at("exact").is_null());
  EXPECT_EQ(null_non_finite_words(R"({"a": -1.5e3, "b": "-Infinity"})"),
            R"({"a": -1.5e3, "b": "-Infinity"})");
}

TEST(JsonText, AKeyAnObjectHoldsTwiceIsRefusedWithItsPath) {
  EXPECT_EQ(parse_json_unique_keys(R"({"a": {"b": 1}, "c": [{"b": 2}, {"b": 3}]})", "f.jsonl:4")["c"][1]["b"],
            3);
  try {
    (void)parse_json_unique_keys(R"({"a": 1, "c": [{"b": 2}, {"b": 3, "d": 0, "b": 4}], "a": 5})",
                                 "f.jsonl:4");
    FAIL() << "a duplicate key parsed";
  } catch (const ConfigError& e) {
    // The first one in the text is named, with its place in the line's value.
    EXPECT_EQ(std::string(e.what()),
              "f.jsonl:4: /c/1/b: duplicate key 'b'; allowed: each key once (JSON keeps only the last)");
  }
  // Syntax and depth come first, as in parse_json_bounded.
  EXPECT_THROW((void)parse_json_unique_keys(R"({"a": 1, "a": )", "f"), nlohmann::json::parse_error);
  EXPECT_THROW((void)parse_json_unique_keys(nested(kMaxJsonNesting + 1), "f"), ConfigError);
}

}  // namespace
}  // namespace fsweep
