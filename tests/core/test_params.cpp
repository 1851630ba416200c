// Declared parameters (src/core/params.hpp) and the registry template (src/core/registry.hpp).

#include <gtest/gtest.h>

#include <cmath>
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
