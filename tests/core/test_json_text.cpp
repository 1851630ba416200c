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

}  // namespace
}  // namespace fsweep
