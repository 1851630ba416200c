#pragma once
/// @file sweep_json_reader.hpp
/// The text of a sweep file parsed into JSON, with the checks a parse must make itself: the
/// nesting depth is bounded (kMaxSweepNesting), duplicate keys are problems, and every parse
/// failure (bad syntax, a number out of range, too deep) is a ConfigError
/// "<file>:<line>:<column>: <what>" in plain words.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace fsweep {
inline namespace sweep {

/// The deepest nesting of arrays and objects a sweep file may have (the top-level object is
/// level 1). Real sweeps use at most 6; the bound keeps every later recursive walk of the
/// value (copies, comparisons, messages) within the stack.
inline constexpr int kMaxSweepNesting = 64;

/// A parsed sweep file and the problems found while parsing ("<JSON path>: <message>", e.g.
/// duplicate keys), which SweepPlan reports with the rest.
struct SweepJson {  // NOLINT(bugprone-exception-escape): json's default constructor is not noexcept; no
                    // caller relies on it
  nlohmann::json value;
  std::vector<std::string> problems;
};

/// Parses `text`, the contents of the sweep file `path`. Throws ConfigError (where() = path)
/// for text that is not JSON, a number beyond the range of a double (1e400) and nesting deeper
/// than kMaxSweepNesting, naming the line, column and, where the parse got that far, the JSON path.
[[nodiscard]] SweepJson parse_sweep_json(const std::string& text, const std::string& path);

}  // namespace sweep
}  // namespace fsweep
