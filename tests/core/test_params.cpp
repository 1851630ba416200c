// Declared parameters (src/core/params.hpp) and the registry template (src/core/registry.hpp).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/config_error.hpp"
#include "core/params.hpp"
#include "core/registry.hpp"

namespace fsweep {
namespace {

using nlohmann::json;

enum class Mode { Fast, Exact };

struct Toy {
  double weight = 2.5;
  int count = 3;
  long budget = 0;
  bool flag = true;
  std::string kind = "a";
  Mode mode = Mode::Exact;
};

ParamDecl<Toy> toy_params() {
  ParamDecl<Toy> d;
  d.number("weight", &Toy::weight, "a weight").range(0, 10).unit("m");
  d.integer("count", &Toy::count, "a count").range(1, 5);
  d.integer("budget", &Toy::budget, "a budget").at_least(0);
  d.boolean("flag", &Toy::flag, "a flag");
  d.choice("kind", &Toy::kind, {"a", "b"}, "a kind");
  d.choice("mode", &Toy::mode, {{"fast", Mode::Fast}, {"exact", Mode::Exact}}, "a mode");
  return d;
}

std::string error_of(const json& given, const std::string& where) {
  try {
    (void)toy_params().read(given, where);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(ParamDecl, DefaultsComeFromTheStructAndWriteResolvesEveryParameter) {
  const ParamDecl<Toy> d = toy_params();
  EXPECT_EQ(d.specs().size(), 6U);
  EXPECT_EQ(d.specs()[0].default_value, json(2.5));
  EXPECT_EQ(d.specs()[5].default_value, json("exact"));
  EXPECT_EQ(
      d.write(d.read(nullptr, "/p")),
      (json{{"weight", 2.5}, {"count", 3}, {"budget", 0}, {"flag", true}, {"kind", "a"}, {"mode", "exact"}}));
}

TEST(ParamDecl, ReadsTypedValues) {
  const Toy t = toy_params().read(json{{"weight", 10},
                                       {"count", 5},
                                       {"budget", 1000000000000LL},
                                       {"flag", false},
                                       {"kind", "b"},
                                       {"mode", "fast"}},
                                  "/p");
  EXPECT_EQ(t.weight, 10.0);
  EXPECT_EQ(t.count, 5);
  EXPECT_EQ(t.budget, 1000000000000L);
  EXPECT_FALSE(t.flag);
  EXPECT_EQ(t.kind, "b");
  EXPECT_EQ(t.mode, Mode::Fast);
}

TEST(ParamDecl, ReportsEveryProblemWithItsPathAndWhatIsAllowed) {
  const std::string m =
      error_of(json{{"weight", 11}, {"count", 1.5}, {"kind", "c"}, {"colour", 1}}, "/s/params");
  EXPECT_NE(m.find("/s/params/weight: value 11 out of range; allowed: a number in [0, 10]"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("/s/params/count: value 1.5 not allowed; allowed: an integer in [1, 5]"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("/s/params/kind: value \"c\" not allowed; allowed: one of \"a\", \"b\""),
            std::string::npos)
      << m;
  EXPECT_NE(
      m.find("/s/params/colour: unknown key 'colour'; allowed: weight, count, budget, flag, kind, mode"),
      std::string::npos)
      << m;
  // Command-line options name the key after the option.
  EXPECT_NE(error_of(json{{"flag", 1}}, "--param")
                .find("--param: flag: value 1 not allowed; allowed: true or false"),
            std::string::npos);
  // Not an object; integers beyond 2^53 (what a double holds exactly); one problem sets where().
  EXPECT_NE(error_of(json::array(), "/p").find("/p: expected an object of parameters"), std::string::npos);
  EXPECT_NE(error_of(json{{"budget", 18446744073709551615ULL}}, "/p")
                .find("/p/budget: value 18446744073709551615 out of range"),
            std::string::npos);
  try {
    (void)toy_params().read(json{{"count", 0}}, "/p");
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.where(), "/p/count");
  }
}

TEST(ParamSpec, AllowedTextNamesOpenAndClosedBounds) {
  ParamDecl<Toy> d;
  d.number("weight", &Toy::weight, "w").range(0, 1).above(0);
  EXPECT_EQ(d.specs()[0].allowed(), "a number in (0, 1]");
  EXPECT_TRUE(d.specs()[0].check(json(0.0)).has_value());
  EXPECT_FALSE(d.specs()[0].check(json(1.0)).has_value());
  EXPECT_TRUE(d.specs()[0].check(json(std::nan(""))).has_value());
}

struct Outer {
  Toy inner;
  double limit = std::numeric_limits<double>::infinity();
};

ParamDecl<Outer> outer_params() {
  ParamDecl<Outer> d;
  d.object("inner", &Outer::inner, toy_params(), "a nested params object");
  d.number_or_none("limit", &Outer::limit, "a limit; null: none").above(0).unit("s");
  return d;
}

TEST(ParamDecl, NestedObjectsAreReadByTheirOwnDeclarationWithFullPaths) {
  const ParamDecl<Outer> d = outer_params();
  EXPECT_EQ(d.specs()[0].type, ParamType::Object);
  ASSERT_TRUE(d.specs()[0].fields);
  EXPECT_EQ(d.specs()[0].fields->size(), 6U);
  EXPECT_EQ(d.specs()[0].allowed(), "an object with keys weight, count, budget, flag, kind, mode");
  const Outer o = d.read(json{{"inner", {{"count", 2}, {"kind", "b"}}}}, "/robot");
  EXPECT_EQ(o.inner.count, 2);
  EXPECT_EQ(o.inner.kind, "b");
  EXPECT_EQ(o.inner.weight, 2.5);  // the inner defaults
  EXPECT_EQ(d.write(o)["inner"]["count"], 2);
  EXPECT_EQ(d.write(o)["inner"]["weight"], 2.5);
  try {
    (void)d.read(json{{"inner", {{"count", 9}, {"color", 1}}}, {"limit", 0}}, "/robot");
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("/robot/inner/count: value 9 out of range; allowed: an integer in [1, 5]"),
              std::string::npos)
        << m;
    EXPECT_NE(m.find("/robot/inner/color: unknown key 'color'"), std::string::npos) << m;
    EXPECT_NE(m.find("/robot/limit: value 0 out of range; allowed: a number > 0, or null"), std::string::npos)
        << m;
  }
  EXPECT_NE(std::string([&] {
              try {
                (void)d.read(json{{"inner", 3}}, "/robot");
              } catch (const ConfigError& e) {
                return std::string(e.what());
              }
              return std::string();
            }())
                .find("/robot/inner: value 3 not allowed; allowed: an object with keys"),
            std::string::npos);
}

TEST(ParamDecl, NumberOrNoneMapsNullToInfinityBothWays) {
  const ParamDecl<Outer> d = outer_params();
  EXPECT_EQ(d.specs()[1].default_value, json());
  EXPECT_EQ(d.read(json{{"limit", nullptr}}, "/p").limit, std::numeric_limits<double>::infinity());
  EXPECT_EQ(d.read(json{{"limit", 0.25}}, "/p").limit, 0.25);
  EXPECT_EQ(d.write(d.read(json{{"limit", 0.25}}, "/p"))["limit"], 0.25);
  EXPECT_TRUE(d.write(Outer{})["limit"].is_null());
}

TEST(Registry, ConfiguresOnceAndListsNamesAndDeclarations) {
  Registry<int, int> r("toy");
  r.add<Toy>("toy", "a toy plugin", toy_params(), [](const Toy& t, int k) { return t.count * k; });
  EXPECT_EQ(r.names(), std::vector<std::string>{"toy"});
  EXPECT_EQ(r.doc("toy"), "a toy plugin");
  EXPECT_EQ(r.params("toy").size(), 6U);
  const auto c = r.configure("toy", json{{"count", 4}}, "/x");
  EXPECT_EQ(c.name, "toy");
  EXPECT_EQ(c.params["count"], 4);
  EXPECT_EQ(c.params["weight"], 2.5);  // defaults resolved
  EXPECT_EQ(c.make(10), 40);           // the maker sees the typed params
  try {
    (void)r.configure("tyo", nullptr, "/x/name");
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.where(), "/x/name");
    EXPECT_NE(std::string(e.what()).find("unknown toy 'tyo'; known: toy"), std::string::npos) << e.what();
  }
  EXPECT_THROW(r.add<Toy>("toy", "again", toy_params(), [](const Toy&, int) { return 0; }), std::logic_error);
}

}  // namespace
}  // namespace fsweep
