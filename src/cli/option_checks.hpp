#pragma once
/// @file option_checks.hpp
/// What CLI11 leaves unchecked or words as a library: numbers that its conversions accept
/// wrongly (CLI11 2.1 reads "-1" into an unsigned option as 2^64 - 1 and "010" as octal 8), and
/// parse errors that do not name what is wrong ("A subcommand is required" for an unknown
/// command). main() applies both to every subcommand, so no option needs its own patch. Also the
/// options several commands share (--max-memory, a sweep's positionals).

#include <CLI/CLI.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "core/memory_limit.hpp"

namespace fsweep::cli {

/// A check that the number given is > 0 ("must be > 0, got '-1'"); CLI11's PositiveNumber
/// words it as a range up to the largest double.
[[nodiscard]] CLI::Validator positive();

/// A check that the number given is >= 0 ("must be >= 0, got '-1'").
[[nodiscard]] CLI::Validator non_negative();

/// Adds a check to every option of `app` and its subcommands by the type CLI11 reads into:
/// unsigned integers (type UINT) must be written as decimal integers >= 0 within 64 bits, signed
/// ones (INT) as decimal integers, floating-point ones (FLOAT) as numbers. Leading zeros are
/// dropped (decimal, never octal). Each message names the option, the value and what is allowed.
/// Call it after every option is added and before parsing.
void check_number_options(CLI::App& app);

/// The message for a parse error of `app` (which has `require_subcommand(1)`): an unknown or
/// missing command names the word and lists the commands; any other error is prefixed with the
/// command being parsed and ends with where to find its options. One or more lines, no newline
/// at the end.
[[nodiscard]] std::string parse_error_message(const CLI::App& app, const CLI::ParseError& e);

/// The limit --max-memory SIZE gives (`fsweep run`, `fsweep merge`): a number of bytes or a number
/// with K, M, G or T (core/memory_limit.hpp's parse_memory_size()). Throws ConfigError naming the
/// option and what is allowed.
[[nodiscard]] MemoryLimit parse_max_memory(const std::string& s);

/// The positionals of a command that reads a sweep (`run`, `expand`, `slurm`): the sweep file
/// (required) and its PATH=VALUE overrides, with `overrides_note` appended to the overrides'
/// help (empty for none).
void add_sweep_positionals(CLI::App& sub, std::string& sweep_file, std::vector<std::string>& overrides,
                           std::string_view overrides_note = {});

}  // namespace fsweep::cli
