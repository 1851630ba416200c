#pragma once
/// @file params.hpp
/// Plugin parameters declared as data (in the spirit of OMPL's declareParam): each parameter
/// has a name, a type, a default, an allowed range or set of choices, a unit and a one-line
/// doc. One generic reader, ParamDecl<P>::read(), turns a JSON object into the plugin's typed
/// params struct P and reports every problem with its JSON path; ParamDecl<P>::write() gives
/// the resolved JSON (every parameter, defaults filled in) that run keys and output columns
/// record. `fsweep describe` prints the declarations, so the documentation cannot drift.

#include <functional>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace fsweep {
inline namespace core {

/// JSON type of a parameter value.
enum class ParamType {
  Boolean,  ///< true or false
  Integer,  ///< a JSON integer
  Number,   ///< any finite JSON number
  Text,     ///< a string
  Choice,   ///< one of ParamSpec::choices (strings)
  Custom,   ///< checked by ParamSpec::custom_check; ParamSpec::allowed_text says what is allowed
  Object,   ///< an object of parameters with their own declarations (ParamSpec::fields)
};

[[nodiscard]] std::string_view to_string(ParamType type);

struct ParamSpec;
/// The declared parameters of one plugin, in declaration order.
using ParamSpecs = std::vector<ParamSpec>;

/// One declared parameter.
// NOLINTNEXTLINE(bugprone-exception-escape): false positive inside nlohmann::json's noexcept move
struct ParamSpec {
  std::string name;
  ParamType type = ParamType::Number;
  /// The resolved value when the key is absent (JSON null: "none").
  nlohmann::json default_value;
  /// Inclusive bounds of Integer and Number values; `*_open` makes a bound exclusive.
  std::optional<double> min;
  std::optional<double> max;
  bool min_open = false;
  bool max_open = false;
  /// Allowed strings of a Choice.
  std::vector<std::string> choices;
  /// JSON null is accepted (meaning "none") besides the typed values.
  bool nullable = false;
  /// Unit of the value ("m", "s", "1/m"), empty when it has none.
  std::string unit;
  /// Left out of the resolved parameters (ParamDecl::write) while at its default: for a
  /// parameter added after run keys existed, so that runs which do not set it keep their keys.
  bool omitted_at_default = false;
  /// One line: what the parameter does (paper equation where it has one).
  std::string doc;
  /// Custom: what is allowed, for messages and `fsweep describe`.
  std::string allowed_text;
  /// Custom: the problems of a value (messages without the path); empty when it is allowed.
  std::function<std::vector<std::string>(const nlohmann::json&)> custom_check;
  /// Object: the declarations of its keys.
  std::shared_ptr<const ParamSpecs> fields;
  /// Problems inside a value check() allowed (an object's keys, a nested plugin's params),
  /// each "<path>: <message>" with its full path; `path` is this parameter's own.
  std::function<std::vector<std::string>(const nlohmann::json& value, const std::string& path)>
      nested_problems;

  /// What is allowed, in words: "a number in [0, 250]", "one of \"path\", \"octile\"", ...
  [[nodiscard]] std::string allowed() const;
  /// The problem with `value`, or nothing when it is allowed.
  [[nodiscard]] std::optional<std::string> check(const nlohmann::json& value) const;
};

/// Where a parameter's problem is reported: "`where`: `key`" when `where` names a command-line
/// option ("--param") or a map spec string (holds a space or quote), "`where`.`key`" inside a
/// named option's parameter ("--robot: sensor.range_m"), else the path `where`/`key`.
[[nodiscard]] std::string param_path(const std::string& where, const std::string& key);

/// The problems of a params object against `specs`, each "<param_path>: <message>" (unknown
/// keys list the allowed ones; a non-object is one problem at `where`). Null is the empty object.
[[nodiscard]] std::vector<std::string> param_problems(const ParamSpecs& specs, const nlohmann::json& given,
                                                      const std::string& where);

/// Throws one ConfigError listing `problems` one per line (each names its own JSON path; with
/// one problem, ConfigError::where() is that path); nothing when empty.
void throw_problems(const std::vector<std::string>& problems);

/// The declaration of a params struct P: the specs plus, per parameter, how its value is
/// stored into and loaded from P. Defaults are P{}'s in-class defaults.
template <class P>
class ParamDecl {
 public:
  /// Chains settings onto the parameter just declared.
  class Builder {
   public:
    explicit Builder(ParamSpec& spec) : spec_(spec) {}
    /// Inclusive range [lo, hi].
    Builder& range(double lo, double hi) {
      spec_.min = lo;
      spec_.max = hi;
      return *this;
    }
    Builder& at_least(double lo) {
      spec_.min = lo;
      return *this;
    }
    /// Exclusive lower bound: values > lo.
    Builder& above(double lo) {
      spec_.min = lo;
      spec_.min_open = true;
      return *this;
    }
    Builder& at_most(double hi) {
      spec_.max = hi;
      return *this;
    }
    /// Exclusive upper bound: values < hi.
    Builder& below(double hi) {
      spec_.max = hi;
      spec_.max_open = true;
      return *this;
    }
    Builder& unit(std::string u) {
      spec_.unit = std::move(u);
      return *this;
    }
    /// ParamSpec::omitted_at_default.
    Builder& omitted_at_default() {
      spec_.omitted_at_default = true;
      return *this;
    }

   private:
    ParamSpec& spec_;
  };

  Builder number(std::string name, double P::*member, std::string doc) {
    return add(ParamType::Number, std::move(name), std::move(doc), member);
  }
  Builder integer(std::string name, int P::*member, std::string doc) {
    return add(ParamType::Integer, std::move(name), std::move(doc), member);
  }
  Builder integer(std::string name, long P::*member, std::string doc) {
    return add(ParamType::Integer, std::move(name), std::move(doc), member);
  }
  Builder boolean(std::string name, bool P::*member, std::string doc) {
    return add(ParamType::Boolean, std::move(name), std::move(doc), member);
  }
  Builder text(std::string name, std::string P::*member, std::string doc) {
    return add(ParamType::Text, std::move(name), std::move(doc), member);
  }
  /// A string member restricted to `choices`.
  /// A number where JSON null (and +infinity in P) means "none": a limit that may be absent.
  Builder number_or_none(std::string name, double P::*member, std::string doc) {
    ParamSpec spec;
    spec.name = std::move(name);
    spec.type = ParamType::Number;
    spec.nullable = true;
    spec.doc = std::move(doc);
    return custom(
        std::move(spec),
        [member](P& p, const nlohmann::json& v) {
          p.*member = v.is_null() ? std::numeric_limits<double>::infinity() : v.get<double>();
        },
        [member](const P& p) {
          const double x = p.*member;
          return x == std::numeric_limits<double>::infinity() ? nlohmann::json() : nlohmann::json(x);
        });
  }
  /// A member that is itself a params struct Q, read by `decl`; problems inside it are
  /// reported at their own paths (`where`/name/key).
  template <class Q>
  Builder object(std::string name, Q P::*member, ParamDecl<Q> decl, std::string doc) {
    auto shared = std::make_shared<const ParamDecl<Q>>(std::move(decl));
    ParamSpec spec;
    spec.name = std::move(name);
    spec.type = ParamType::Object;
    spec.doc = std::move(doc);
    spec.fields = std::shared_ptr<const ParamSpecs>(shared, &shared->specs());
    spec.nested_problems = [shared](const nlohmann::json& v, const std::string& path) {
      return param_problems(shared->specs(), v, path);
    };
    return custom(
        std::move(spec), [member, shared](P& p, const nlohmann::json& v) { p.*member = shared->read(v, {}); },
        [member, shared](const P& p) { return shared->write(p.*member); });
  }
  Builder choice(std::string name, std::string P::*member, std::vector<std::string> choices,
                 std::string doc) {
    Builder b = add(ParamType::Choice, std::move(name), std::move(doc), member);
    specs_.back().choices = std::move(choices);
    return b;
  }
  /// An enum member, spelled in JSON by the strings of `choices`.
  template <class E>
  Builder choice(std::string name, E P::*member, std::vector<std::pair<std::string, E>> choices,
                 std::string doc) {
    ParamSpec spec;
    spec.name = std::move(name);
    spec.type = ParamType::Choice;
    spec.doc = std::move(doc);
    for (const auto& c : choices) spec.choices.push_back(c.first);
    return custom(
        std::move(spec),
        [member, choices](P& p, const nlohmann::json& v) {
          for (const auto& [text, value] : choices) {
            if (v == text) p.*member = value;
          }
        },
        [member, choices](const P& p) {
          for (const auto& [text, value] : choices) {
            if (p.*member == value) return nlohmann::json(text);
          }
          return nlohmann::json();
        });
  }
  /// Any other parameter: `store` writes a checked value into P, `load` reads it back as JSON.
  Builder custom(ParamSpec spec, std::function<void(P&, const nlohmann::json&)> store,
                 std::function<nlohmann::json(const P&)> load) {
    spec.default_value = load(P{});
    specs_.push_back(std::move(spec));
    bindings_.push_back({std::move(store), std::move(load)});
    return Builder(specs_.back());
  }

  [[nodiscard]] const ParamSpecs& specs() const { return specs_; }

  /// Reads `given` (an object, or null for all defaults) into P. Every problem (unknown key,
  /// wrong type, out of range) is collected and thrown as one ConfigError, each line naming
  /// its JSON path `where`/key.
  [[nodiscard]] P read(const nlohmann::json& given, const std::string& where) const {
    throw_problems(param_problems(specs_, given, where));
    P p;
    if (given.is_null()) return p;
    for (std::size_t i = 0; i < specs_.size(); ++i) {
      const auto it = given.find(specs_[i].name);
      if (it != given.end()) bindings_[i].store(p, *it);
    }
    return p;
  }

  /// The resolved parameters of `p`: every declared parameter by name (but those
  /// omitted_at_default() while at their default).
  [[nodiscard]] nlohmann::json write(const P& p) const {
    nlohmann::json j = nlohmann::json::object();
    for (std::size_t i = 0; i < specs_.size(); ++i) {
      nlohmann::json value = bindings_[i].load(p);
      if (specs_[i].omitted_at_default && value == specs_[i].default_value) continue;
      j[specs_[i].name] = std::move(value);
    }
    return j;
  }

 private:
  struct Binding {
    std::function<void(P&, const nlohmann::json&)> store;
    std::function<nlohmann::json(const P&)> load;
  };

  template <class T>
  Builder add(ParamType type, std::string name, std::string doc, T P::*member) {
    ParamSpec spec;
    spec.name = std::move(name);
    spec.type = type;
    spec.doc = std::move(doc);
    if constexpr (std::is_same_v<T, int>) {  // what the member can hold, unless range() narrows it
      spec.min = static_cast<double>(std::numeric_limits<int>::min());
      spec.max = static_cast<double>(std::numeric_limits<int>::max());
    }  // long: ParamSpec::check() refuses integers beyond +-2^53 for every Integer
    return custom(
        std::move(spec), [member](P& p, const nlohmann::json& v) { p.*member = v.get<T>(); },
        [member](const P& p) { return nlohmann::json(p.*member); });
  }

  ParamSpecs specs_;
  std::vector<Binding> bindings_;
};

/// A params struct for plugins without parameters.
struct NoParams {};

}  // namespace core
}  // namespace fsweep
