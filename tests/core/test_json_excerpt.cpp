// json_excerpt (src/core/json_excerpt.hpp): values in messages are bounded in size and depth.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "core/json_excerpt.hpp"

namespace fsweep {
namespace {

using nlohmann::json;

TEST(JsonExcerpt, ShortValuesAsDumpWritesThem) {
  for (const json& v :
       {json(1), json(2.5), json("abc"), json(nullptr), json::parse(R"({"a":[1,{"b":true}]})")}) {
    EXPECT_EQ(json_excerpt(v), v.dump());
  }
}

TEST(JsonExcerpt, LongStringIsCutToTheLimit) {
  const std::string text = json_excerpt(json(std::string(200'000, 'x')), 20);
  EXPECT_EQ(text, std::string(1, '"').append(19, 'x').append("..."));
}

TEST(JsonExcerpt, LongArrayIsCutToTheLimit) {
  const json big(std::vector<int>(100'000, 7));
  const std::string text = json_excerpt(big, 10);
  EXPECT_EQ(text, "[7,7,7,7,7...");
}

TEST(JsonExcerpt, DeepNestingIsCutWithoutRecursingIntoIt) {
  // Built iteratively: 100,000 levels (dump() of this value would recurse 100,000 deep).
  json deep = json::array();
  for (int i = 0; i < 100'000; ++i) deep = json::array({std::move(deep)});
  const std::string text = json_excerpt(deep);
  EXPECT_EQ(text, std::string(kMaxExcerptDepth, '[').append("[...]").append(kMaxExcerptDepth, ']'));
}

TEST(JsonExcerpt, LongKeyIsCut) {
  const json obj{{std::string(500, 'k'), 1}};
  EXPECT_EQ(json_excerpt(obj, 12), std::string("{\"").append(10, 'k').append("..."));
}

}  // namespace
}  // namespace fsweep
