#pragma once
/// @file registry.hpp
/// One registry template for every plugin kind (strategies, planners, map generators, energy
/// presets): names to declared parameters (params.hpp) and a maker. Each kind fills its one
/// registry explicitly in one place (no static self-registration); the same registry serves
/// JSON, the command line (`fsweep describe`) and the tests.

#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/config_error.hpp"
#include "core/params.hpp"

namespace fsweep {
inline namespace core {

/// What `fsweep describe` and messages need from a registry of any kind.
class RegistryView {
 public:
  virtual ~RegistryView() = default;
  /// The plugin kind in the singular, as in messages: "strategy", "planner", ...
  [[nodiscard]] virtual const std::string& kind() const = 0;
  /// Every registered name, sorted.
  [[nodiscard]] virtual std::vector<std::string> names() const = 0;
  [[nodiscard]] virtual bool contains(const std::string& name) const = 0;
  /// One line on what plugin `name` is (paper, equation). Throws ConfigError for an unknown name.
  [[nodiscard]] virtual const std::string& doc(const std::string& name) const = 0;
  /// The declared parameters of `name`, in declaration order. Throws ConfigError for an
  /// unknown name.
  [[nodiscard]] virtual const ParamSpecs& params(const std::string& name) const = 0;
};

/// Plugins that make a `Product` from `Args...` (e.g. a strategy from the run seed).
template <class Product, class... Args>
class Registry final : public RegistryView {
 public:
  using Maker = std::function<Product(Args...)>;

  /// A plugin resolved once from its JSON: its name, its resolved parameters (every declared
  /// parameter, defaults filled in: what run keys and output columns record) and a maker
  /// bound to the typed params.
  // NOLINTNEXTLINE(bugprone-exception-escape): false positive inside nlohmann::json's noexcept move
  struct Configured {
    std::string name;
    nlohmann::json params;
    Maker make;
  };

  explicit Registry(std::string kind) : kind_(std::move(kind)) {}

  /// Registers plugin `name` with params struct P declared by `declare()` (called once, on
  /// first use: declarations may be costly to build, e.g. OMPL's are read from OMPL) and
  /// `make`, which builds the product from the typed params. A repeated name is a logic error.
  template <class P>
  void add(std::string name, const std::string& doc, std::function<ParamDecl<P>()> declare,
           std::function<Product(const P&, Args...)> make) {
    auto lazy = std::make_shared<Lazy<P>>();
    lazy->declare = std::move(declare);
    Entry entry;
    entry.doc = doc;
    entry.specs = [lazy]() -> const ParamSpecs& { return lazy->get().specs(); };
    entry.configure = [lazy, make = std::move(make), name](const nlohmann::json& given,
                                                           const std::string& where) {
      const ParamDecl<P>& decl = lazy->get();
      P typed = decl.read(given, where);
      Configured c;
      c.name = name;
      c.params = decl.write(typed);
      c.make = [typed = std::move(typed), make](Args... args) { return make(typed, args...); };
      return c;
    };
    if (!entries_.emplace(std::move(name), std::move(entry)).second) {
      throw std::logic_error("Registry: a " + kind_ + " is registered twice");
    }
  }

  /// The same with a declaration that is cheap to build.
  template <class P>
  void add(std::string name, const std::string& doc, ParamDecl<P> decl,
           std::function<Product(const P&, Args...)> make) {
    add<P>(std::move(name), doc, std::function<ParamDecl<P>()>([decl] { return decl; }), std::move(make));
  }

  /// Resolves plugin `name` with the JSON params `given` (an object, or null for defaults).
  /// Throws ConfigError at `where` for an unknown name (listing the known ones), or one
  /// ConfigError listing every bad parameter at `params_where`/<key> (default: `where`/params;
  /// see param_path()).
  [[nodiscard]] Configured configure(const std::string& name, const nlohmann::json& given,
                                     const std::string& where, const std::string& params_where = {}) const {
    return entry(name, where).configure(given, params_where.empty() ? where + "/params" : params_where);
  }

  [[nodiscard]] const std::string& kind() const override { return kind_; }
  [[nodiscard]] std::vector<std::string> names() const override {
    std::vector<std::string> out;
    out.reserve(entries_.size());
    for (const auto& [name, e] : entries_) out.push_back(name);
    return out;
  }
  [[nodiscard]] bool contains(const std::string& name) const override { return entries_.count(name) > 0; }
  [[nodiscard]] const std::string& doc(const std::string& name) const override {
    return entry(name, kind_).doc;
  }
  [[nodiscard]] const ParamSpecs& params(const std::string& name) const override {
    return entry(name, kind_).specs();
  }

 private:
  template <class P>
  struct Lazy {
    std::function<ParamDecl<P>()> declare;
    std::once_flag once;
    std::optional<ParamDecl<P>> decl;
    const ParamDecl<P>& get() {
      std::call_once(once, [this] { decl.emplace(declare()); });
      return *decl;
    }
  };

  struct Entry {
    std::string doc;
    std::function<const ParamSpecs&()> specs;
    std::function<Configured(const nlohmann::json&, const std::string&)> configure;
  };

  const Entry& entry(const std::string& name, const std::string& where) const {
    const auto it = entries_.find(name);
    if (it == entries_.end()) {
      throw ConfigError(where, "unknown " + kind_ + " '" + name + "'; known: " + join_names(names()));
    }
    return it->second;
  }

  std::string kind_;
  std::map<std::string, Entry> entries_;
};

}  // namespace core
}  // namespace fsweep
