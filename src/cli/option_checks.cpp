#include "cli/option_checks.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "core/config_error.hpp"

namespace fsweep::cli {
namespace {

/// `text` without leading zeros after an optional '-' ("007" -> "7", "-00" -> "-0"), or "" if it
/// is not an optional '-' followed by decimal digits.
std::string decimal_integer(const std::string& text, bool allow_minus) {
  std::size_t start = allow_minus && !text.empty() && text[0] == '-' ? 1 : 0;
  if (start == text.size()) return "";
  if (!std::all_of(text.begin() + static_cast<std::ptrdiff_t>(start), text.end(),
                   [](char c) { return c >= '0' && c <= '9'; })) {
    return "";
  }
  std::size_t first = text.find_first_not_of('0', start);
  if (first == std::string::npos) first = text.size() - 1;  // all zeros: keep one
  return text.substr(0, start) + text.substr(first);
}

std::string in_quotes(const std::string& text) { return "'" + text + "'"; }

std::string check_unsigned(std::string& text) {
  const std::string digits = decimal_integer(text, /*allow_minus=*/false);
  if (digits.empty()) return "must be an integer >= 0, got " + in_quotes(text);
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec != std::errc() || end != digits.data() + digits.size()) {
    return "must be an integer from 0 to 18446744073709551615 (2^64 - 1), got " + in_quotes(text);
  }
  text = digits;
  return "";
}

std::string check_signed(std::string& text) {
  const std::string digits = decimal_integer(text, /*allow_minus=*/true);
  if (digits.empty()) return "must be an integer, got " + in_quotes(text);
  text = digits;
  return "";
}

/// `text` as a double, or nothing if it is not a number from start to end or is out of range.
std::optional<double> parse_double(const std::string& text) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::string check_number(const std::string& text) {
  return parse_double(text) ? "" : "must be a number, got " + in_quotes(text);
}

/// Every command of `app`, `app` first.
void collect_apps(CLI::App& app, std::vector<CLI::App*>& out) {
  out.push_back(&app);
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) collect_apps(*sub, out);
}

/// The names of `app`'s commands, comma separated.
std::string command_names(const CLI::App& app) {
  std::string out;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    out += (out.empty() ? "" : ", ") + sub->get_name();
  }
  return out;
}

/// A check that the text is a number above `min` (or equal to it when `inclusive`).
CLI::Validator bounded_below(double min, bool inclusive, const std::string& name) {
  return CLI::Validator(
      [min, inclusive](const std::string& text) {
        const std::optional<double> value = parse_double(text);
        if (value && (*value > min || (inclusive && *value == min))) return std::string();
        return std::string(inclusive ? "must be >= " : "must be > ") +
               (min == 0.0 ? "0" : std::to_string(min)) + ", got " + in_quotes(text);
      },
      "", name);
}

}  // namespace

CLI::Validator positive() { return bounded_below(0.0, /*inclusive=*/false, "POSITIVE"); }

CLI::Validator non_negative() { return bounded_below(0.0, /*inclusive=*/true, "NON_NEGATIVE"); }

void check_number_options(CLI::App& app) {
  std::vector<CLI::App*> apps;
  collect_apps(app, apps);
  for (CLI::App* a : apps) {
    for (CLI::Option* option : a->get_options()) {
      // The type without the descriptions of checks already added ("INT:INT in [0 - 7]").
      const std::string full = option->get_type_name();
      const std::string type = full.substr(0, full.find(':'));
      // transform(): runs before any other check and may rewrite the text (leading zeros).
      if (type == "UINT") {
        option->transform(
            CLI::Validator([](std::string& text) { return check_unsigned(text); }, "", "UINT64"));
      } else if (type == "INT") {
        option->transform(
            CLI::Validator([](std::string& text) { return check_signed(text); }, "", "INTEGER"));
      } else if (type == "FLOAT") {
        option->transform(
            CLI::Validator([](const std::string& text) { return check_number(text); }, "", "NUMBER"));
      }
    }
  }
}

std::string parse_error_message(const CLI::App& app, const CLI::ParseError& e) {
  const std::vector<CLI::App*> parsed = app.get_subcommands();
  if (parsed.empty()) {
    const std::vector<std::string> words = app.remaining();
    const std::string commands = command_names(app);
    if (words.empty()) return "fsweep: error: a command is required; allowed: " + commands;
    return "fsweep: error: unknown command '" + words.front() + "'; allowed: " + commands +
           " (fsweep --help describes them)";
  }
  const std::string name = parsed.back()->get_name();
  return "fsweep: error: " + name + ": " + e.what() + "\n(fsweep " + name + " --help lists its options)";
}

MemoryLimit parse_max_memory(const std::string& s) {
  const std::optional<std::uint64_t> bytes = parse_memory_size(s);
  if (!bytes) {
    throw ConfigError("--max-memory",
                      "expected a size above 0: a number of bytes, or a number with K, M, G or T (powers of "
                      "1024) such as 512M, 1.5G or 4G; got '" +
                          s + "'");
  }
  return MemoryLimit{*bytes, "--max-memory " + s};
}

void add_sweep_positionals(CLI::App& sub, std::string& sweep_file, std::vector<std::string>& overrides,
                           std::string_view overrides_note) {
  sub.add_option("sweep", sweep_file, "Sweep file (JSON)")->required();
  sub.add_option("overrides", overrides,
                 "PATH=VALUE overrides of the sweep, applied before validation (robot.battery=800, "
                 "'strategies[0].params.w1=[0,10]'; VALUE is JSON when it parses, else a string)" +
                     std::string(overrides_note));
}

}  // namespace fsweep::cli
