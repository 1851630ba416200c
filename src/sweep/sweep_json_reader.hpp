#pragma once
/// @file sweep_json_reader.hpp
/// The text of a sweep file parsed into JSON, with the checks a parse must make itself: the
/// nesting depth is bounded (kMaxSweepNesting), duplicate keys are problems, and every parse
/// failure (bad syntax, a number out of range, too deep) is a ConfigError
/// "<file>:<line>:<column>: <what>" in plain words. And the command line's overrides of a sweep
/// (`fsweep run SWEEP.json robot.battery=800`), applied to the parsed JSON before validation.

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace fsweep {
inline namespace sweep {

/// The deepest nesting of arrays and objects a sweep file may have (the top-level object is
/// level 1). Real sweeps use at most 6; the bound keeps every later recursive walk of the
/// value (copies, comparisons, messages) within the stack.
inline constexpr int kMaxSweepNesting = 64;

/// The longest override (`PATH=VALUE` together) a sweep takes; a longer value belongs in the
/// sweep file (and Linux passes at most 128 KiB as one command-line argument).
inline constexpr std::size_t kMaxOverrideChars = 65'536;

/// One command-line override of a sweep, as applied by apply_sweep_overrides().
struct SweepOverride {
  std::string text;     ///< as given: "strategies[1].params.w1=[1,2,3]"
  std::string pointer;  ///< its path as a JSON pointer: "/strategies/1/params/w1"
};

/// A parsed sweep file, the problems found while parsing ("<JSON path>: <message>", e.g.
/// duplicate keys), which SweepPlan reports with the rest, and the overrides applied to it.
struct SweepJson {  // NOLINT(bugprone-exception-escape): json's default constructor is not noexcept; no
                    // caller relies on it
  nlohmann::json value;
  std::vector<std::string> problems;
  std::vector<SweepOverride> overrides;
};

/// Parses `text`, the contents of the sweep file `path`. Throws ConfigError (where() = path)
/// for text that is not JSON, a number beyond the range of a double (1e400) and nesting deeper
/// than kMaxSweepNesting, naming the line, column and, where the parse got that far, the JSON path.
[[nodiscard]] SweepJson parse_sweep_json(const std::string& text, const std::string& path);

/// Applies `overrides`, each "PATH=VALUE" (docs/sweeps.md, "Overrides on the command line"), in
/// order to the sweep `parsed` read from `path`. PATH is a dotted path of keys (letters, digits,
/// '_', '-') with [i] for list entries ("strategies[1].params.w1"); it sets that value, adding
/// an object key (and objects on the way) that is not there. VALUE is JSON when it parses as
/// JSON (numbers, true/false/null, lists, objects, quoted strings), else the text itself as a
/// string; a value starting with '[', '{' or '"' must be JSON. Duplicate keys in a value are
/// problems, as in the file. Throws ConfigError (where() = path) listing every override that
/// cannot be applied: no '=', a malformed path, a list entry that is not there (entries are set,
/// not added), a step through something that is not an object or list, the same path twice,
/// longer than kMaxOverrideChars, nested deeper than kMaxSweepNesting, not UTF-8.
[[nodiscard]] SweepJson apply_sweep_overrides(SweepJson parsed, const std::vector<std::string>& overrides,
                                              const std::string& path);

/// "override '<text>'" for messages, the text cut to 80 characters.
[[nodiscard]] std::string override_label(const std::string& text);

}  // namespace sweep
}  // namespace fsweep
