/// @file describe_command.cpp
/// `fsweep describe [KIND [NAME]]`: the kinds, the names of one plugin kind, or one plugin's
/// declared parameters (type, default, allowed values, unit, doc), printed from the registries'
/// declarations (core/params.hpp), so it cannot drift from what the readers accept. The robot
/// and sim settings are kinds without names: `fsweep describe robot` prints their parameters,
/// nested objects flattened (`sensor.range_m`).

#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "core/config_error.hpp"
#include "core/registry.hpp"
#include "planners/registry.hpp"
#include "sim/run_spec.hpp"
#include "strategies/registry.hpp"
#include "world/energy_model.hpp"
#include "world/map_generators.hpp"

namespace fsweep::cli {
namespace {

/// A plugin kind (a registry of names) or a settings kind (one set of parameters).
struct Kind {
  const char* name;
  const char* what;
  const RegistryView* registry = nullptr;
  const ParamSpecs* settings = nullptr;
};

std::vector<Kind> kinds() {
  return {
      {"planner", "path planners: the \"planners\" of a sweep, fsweep plan --planner", &planner_registry()},
      {"strategy", "exploration strategies: the \"strategies\" of a sweep, fsweep sim --strategy",
       &strategy_registry()},
      {"generator", "map generators: map SPEC \"KIND:key=value,...\" or {\"generator\": KIND, ...}",
       &generator_registry()},
      {"energy", "energy presets: robot \"energy\": NAME or {\"preset\": NAME, overrides}",
       &energy_registry()},
      {"robot", "the robot: the \"robot\" object of a sweep, fsweep sim --robot", nullptr,
       &robot_params().specs()},
      {"sim", "loop settings: the \"sim\" object of a sweep, fsweep sim --sim", nullptr,
       &sim_params().specs()}};
}

/// `specs` with every Object parameter replaced by its fields, named "<object>.<field>".
ParamSpecs flattened(const ParamSpecs& specs, const std::string& prefix = {}) {
  ParamSpecs out;
  for (const ParamSpec& s : specs) {
    if (s.type == ParamType::Object && s.fields) {
      for (ParamSpec& f : flattened(*s.fields, prefix + s.name + ".")) out.push_back(std::move(f));
    } else {
      out.push_back(s);
      out.back().name = prefix + s.name;
    }
  }
  return out;
}

struct DescribeOptions {
  std::string kind;
  std::string name;
  std::string format = "text";
};

std::string value_text(const nlohmann::json& v) {
  if (v.is_null()) return "none";
  return v.is_string() ? v.get<std::string>() : v.dump();
}

/// Prints `rows` as left-aligned columns separated by two spaces (the last column unpadded).
void print_table(const std::vector<std::vector<std::string>>& rows) {
  std::vector<std::size_t> width;
  for (const auto& row : rows) {
    width.resize(std::max(width.size(), row.size()), 0);
    for (std::size_t k = 0; k + 1 < row.size(); ++k) width[k] = std::max(width[k], row[k].size());
  }
  for (const auto& row : rows) {
    std::string line;
    for (std::size_t k = 0; k < row.size(); ++k) {
      line += row[k];
      if (k + 1 < row.size()) line += std::string(width[k] - row[k].size() + 2, ' ');
    }
    std::cout << line << '\n';
  }
}

nlohmann::json spec_json(const ParamSpec& s) {
  return {{"name", s.name},
          {"type", std::string(to_string(s.type))},
          {"default", s.default_value},
          {"allowed", s.allowed()},
          {"unit", s.unit},
          {"doc", s.doc}};
}

/// One plugin's or settings kind's parameters in the chosen format, under `title`: `doc`.
int print_params(const DescribeOptions& o, const std::string& title, const std::string& doc,
                 const ParamSpecs& specs) {
  if (o.format == "json") {
    nlohmann::json params = nlohmann::json::array();
    for (const ParamSpec& s : specs) params.push_back(spec_json(s));
    std::cout << nlohmann::json{{"kind", o.kind}, {"name", o.name}, {"doc", doc}, {"params", params}}.dump(2)
              << '\n';
    return 0;
  }
  if (o.format == "markdown") {
    std::cout
        << "| parameter | type | default | allowed | unit | what it does |\n|---|---|---|---|---|---|\n";
    for (const ParamSpec& s : specs) {
      std::cout << "| `" << s.name << "` | " << to_string(s.type) << " | `" << value_text(s.default_value)
                << "` | " << s.allowed() << " | " << s.unit << " | " << s.doc << " |\n";
    }
    return 0;
  }
  std::cout << title << ": " << doc << "\n\n";
  if (specs.empty()) {
    std::cout << "no parameters\n";
    return 0;
  }
  std::vector<std::vector<std::string>> rows{{"parameter", "type", "default", "unit", "allowed", "doc"}};
  for (const ParamSpec& s : specs) {
    rows.push_back({s.name, std::string(to_string(s.type)), value_text(s.default_value),
                    s.unit.empty() ? "-" : s.unit, s.allowed(), s.doc});
  }
  print_table(rows);
  return 0;
}

int describe(const DescribeOptions& o) {
  const std::vector<Kind> all = kinds();
  if (o.kind.empty()) {
    if (o.format == "json") {
      nlohmann::json j = nlohmann::json::object();
      for (const Kind& k : all) j[k.name] = k.registry ? k.registry->names() : std::vector<std::string>{};
      std::cout << j.dump(2) << '\n';
      return 0;
    }
    std::vector<std::vector<std::string>> rows;
    rows.reserve(all.size());
    for (const Kind& k : all) rows.push_back({k.name, k.what});
    print_table(rows);
    std::cout
        << "\nfsweep describe KIND lists the names of a kind (robot, sim: their parameters); fsweep describe "
           "KIND NAME a plugin's parameters.\n";
    return 0;
  }
  const auto kind = std::find_if(all.begin(), all.end(), [&](const Kind& k) { return o.kind == k.name; });
  if (kind == all.end()) {
    std::vector<std::string> names;
    names.reserve(all.size());
    for (const Kind& k : all) names.emplace_back(k.name);
    throw ConfigError("describe", "unknown kind '" + o.kind + "'; known: " + join_names(names));
  }
  if (kind->settings) {
    if (!o.name.empty()) {
      throw ConfigError("describe", std::string(kind->name) + " has no names; fsweep describe " + kind->name +
                                        " prints its parameters");
    }
    return print_params(o, kind->name, kind->what, flattened(*kind->settings));
  }
  const RegistryView& registry = *kind->registry;
  if (o.name.empty()) {
    if (o.format == "json") {
      nlohmann::json j = nlohmann::json::object();
      for (const auto& name : registry.names()) j[name] = registry.doc(name);
      std::cout << j.dump(2) << '\n';
      return 0;
    }
    std::vector<std::vector<std::string>> rows;
    for (const auto& name : registry.names()) rows.push_back({name, registry.doc(name)});
    print_table(rows);
    return 0;
  }
  const ParamSpecs& specs = registry.params(o.name);  // throws for an unknown name, listing the known
  return print_params(o, std::string(kind->name) + " " + o.name, registry.doc(o.name), specs);
}

}  // namespace

Command add_describe_command(CLI::App& app) {
  auto o = std::make_shared<DescribeOptions>();
  CLI::App* sub = app.add_subcommand(
      "describe",
      "List the plugin kinds, the names of a kind, or one plugin's parameters (from their declarations)");
  sub->add_option("kind", o->kind, "planner, strategy, generator, energy, robot or sim");
  sub->add_option("name", o->name, "A name of that kind, e.g. energy_aware");
  sub->add_option("--format", o->format, "text (default), markdown (a README table) or json")
      ->check(CLI::IsMember({"text", "markdown", "json"}));
  return [o] { return describe(*o); };
}

}  // namespace fsweep::cli
