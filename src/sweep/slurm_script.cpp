/// @file slurm_script.cpp
/// Rendering of the `fsweep slurm` scripts (slurm_script.hpp).

#include "sweep/slurm_script.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <sstream>
#include <string_view>

#include "core/config_error.hpp"

namespace fsweep {
inline namespace sweep {
namespace {

bool is_absolute(const std::string& path) { return !path.empty() && path.front() == '/'; }

void require_absolute(const std::string& path, const std::string& what) {
  if (!is_absolute(path)) throw ConfigError(what, "must be an absolute path, got '" + path + "'");
}

/// `s` in single quotes for messages, control characters written as \n, \r, \0 or \xNN (a bad
/// value may hold a newline), cut after 120 characters.
std::string quoted(const std::string& s) {
  constexpr std::size_t kMaxChars = 120;
  std::string out = "'";
  for (std::size_t i = 0; i < s.size() && i < kMaxChars; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == 0) {
      out += "\\0";
    } else if (c < 0x20 || c == 0x7f) {
      constexpr std::string_view kHex = "0123456789abcdef";
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 0xf];
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + (s.size() > kMaxChars ? "'..." : "'");
}

/// Characters that would break an `#SBATCH --opt=value` line (sbatch splits it at whitespace
/// and strips quotes; a NUL would end it).
bool breaks_directive(char c) {
  return c == '\0' || std::isspace(static_cast<unsigned char>(c)) != 0 || c == '"' || c == '\'' || c == '\\';
}

void require_directive_value(const std::string& value, const std::string& what) {
  if (std::any_of(value.begin(), value.end(), breaks_directive)) {
    throw ConfigError(what,
                      "must not contain whitespace, quotes, backslashes or NUL (it goes into an #SBATCH "
                      "line), got " +
                          quoted(value));
  }
}

/// An account or QOS name: empty (not written) or [A-Za-z0-9_.-]+.
void require_slurm_name(const std::string& value, const std::string& what) {
  const auto allowed = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.' || c == '-';
  };
  if (!std::all_of(value.begin(), value.end(), allowed)) {
    throw ConfigError(what, "must be a name of letters, digits, '_', '.' and '-', got " + quoted(value));
  }
}

/// The directives fsweep slurm writes itself, and what to use instead of an --sbatch line.
struct OwnDirective {
  std::string_view option;
  std::string_view instead;
};
constexpr OwnDirective kOwnDirectives[] = {
    {"job-name", "the jobs are named fsweep-<sweep name> and fsweep-<sweep name>-merge"},
    {"array", "the array covers the shards: --tasks, --max-array-size"},
    {"cpus-per-task", "use --cpus"},
    {"output", "the logs go to <out>/slurm/logs"},
    {"partition", "use --partition"},
    {"time", "use --time"},
    {"mem", "use --mem"},
    {"account", "use --account"},
    {"qos", "use --qos"},
    {"gres", "use --gres"},
};

/// An --sbatch line as the directive it becomes, `--option` or `--option=value` (a leading
/// `#SBATCH ` dropped); ConfigError naming --sbatch when it is not one (SlurmScriptOptions).
std::string sbatch_directive(const std::string& line) {
  const std::string allowed =
      "; allowed: --option or --option=value as on sbatch's command line (optionally after '#SBATCH '), "
      "the option of a-z, 0-9 and '-', the value without whitespace, quotes or backslashes";
  std::string_view d(line);
  constexpr std::string_view kPrefix = "#SBATCH ";
  if (d.starts_with(kPrefix)) {
    d.remove_prefix(kPrefix.size());
    while (d.starts_with(' ')) d.remove_prefix(1);
  }
  const std::size_t eq = d.find('=');
  const std::string_view option = d.substr(0, eq);
  const auto option_char = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
  };
  if (!option.starts_with("--") || option.size() < 3 || !(option[2] >= 'a' && option[2] <= 'z') ||
      !std::all_of(option.begin(), option.end(), option_char) ||
      (eq != std::string_view::npos && std::any_of(d.begin() + eq + 1, d.end(), breaks_directive))) {
    throw ConfigError("--sbatch", quoted(line) + " is not an sbatch option" + allowed);
  }
  const std::string_view name = option.substr(2);
  for (const OwnDirective& own : kOwnDirectives) {
    if (own.option.starts_with(name)) {  // sbatch takes an unambiguous abbreviation as the option
      throw ConfigError("--sbatch", quoted(line) + " sets --" + std::string(own.option) +
                                        ", which fsweep slurm writes itself; " + std::string(own.instead));
    }
  }
  return std::string(d);
}

/// A --setup line: one line of shell (no newline, carriage return or NUL).
void require_setup_line(const std::string& line) {
  if (line.find_first_of(std::string_view("\n\r\0", 3)) != std::string::npos) {
    throw ConfigError("--setup", quoted(line) +
                                     " is not one line; allowed: one line of shell each (repeat --setup for "
                                     "more), without newline, carriage return or NUL");
  }
}

void validate(const SlurmScriptOptions& o) {
  require_absolute(o.fsweep, "--fsweep");
  require_absolute(o.sweep_file, "sweep file");
  require_absolute(o.out_dir, "--out");
  require_absolute(o.work_dir, "working directory");
  require_directive_value(o.out_dir, "--out");
  require_directive_value(o.partition, "--partition");
  require_directive_value(o.time, "--time");
  require_directive_value(o.mem, "--mem");
  require_slurm_name(o.account, "--account");
  require_slurm_name(o.qos, "--qos");
  require_directive_value(o.gres, "--gres");
  for (const std::string& line : o.sbatch_lines) (void)sbatch_directive(line);
  for (const std::string& line : o.setup_lines) require_setup_line(line);
  if (o.name.empty()) throw ConfigError("sweep name", "must not be empty");
  require_directive_value(o.name, "sweep name");
  if (o.cpus < 1) throw ConfigError("--cpus", "must be >= 1, got " + std::to_string(o.cpus));
  (void)slurm_array_tasks(o.shards, o.max_array_size);  // checks both
}

/// The path for an `#SBATCH --output=` pattern: '%' is Slurm's pattern character, "%%" a '%'.
std::string escape_pattern(const std::string& path) {
  std::string out;
  for (const char c : path) {
    out += c;
    if (c == '%') out += '%';
  }
  return out;
}

/// The optional directives common to both scripts.
void resource_directives(std::ostringstream& s, const SlurmScriptOptions& o) {
  if (!o.partition.empty()) s << "#SBATCH --partition=" << o.partition << '\n';
  if (!o.time.empty()) s << "#SBATCH --time=" << o.time << '\n';
  if (!o.mem.empty()) s << "#SBATCH --mem=" << o.mem << '\n';
  if (!o.account.empty()) s << "#SBATCH --account=" << o.account << '\n';
  if (!o.qos.empty()) s << "#SBATCH --qos=" << o.qos << '\n';
}

/// The --sbatch lines, after fsweep's own directives.
void extra_directives(std::ostringstream& s, const SlurmScriptOptions& o) {
  for (const std::string& line : o.sbatch_lines) s << "#SBATCH " << sbatch_directive(line) << '\n';
}

/// The --setup lines, as given, with `set -u` off around them (module and conda scripts read
/// unset variables); `restore_nounset` when the script runs with `set -u`.
void setup_block(std::ostringstream& s, const SlurmScriptOptions& o, bool restore_nounset) {
  if (o.setup_lines.empty()) return;
  s << "# setup (fsweep slurm --setup), in order:\n";
  if (restore_nounset) s << "set +u\n";
  for (const std::string& line : o.setup_lines) s << line << '\n';
  if (restore_nounset) s << "set -u\n";
}

}  // namespace

std::uint64_t slurm_array_tasks(std::uint64_t shards, std::uint64_t max_array_size) {
  if (shards == 0) throw ConfigError("--tasks", "must be >= 1 (the number of shards), got 0");
  if (max_array_size == 0) {
    throw ConfigError("MaxArraySize",
                      "is 0: job arrays are disabled on this cluster (or pass --max-array-size >= 1)");
  }
  return std::min(shards, max_array_size);
}

std::vector<std::uint64_t> slurm_task_shards(std::uint64_t task, std::uint64_t shards,
                                             std::uint64_t max_array_size) {
  const std::uint64_t tasks = slurm_array_tasks(shards, max_array_size);
  std::vector<std::uint64_t> out;
  if (task >= tasks) return out;
  for (std::uint64_t s = task; s < shards; s += tasks) {
    out.push_back(s);
    if (shards - s <= tasks) break;  // the next one would be >= shards (and might overflow)
  }
  return out;
}

std::string slurm_dir(const std::string& out_dir) { return out_dir + "/slurm"; }
std::string slurm_log_dir(const std::string& out_dir) { return slurm_dir(out_dir) + "/logs"; }
std::string slurm_array_script_path(const std::string& out_dir) {
  return slurm_dir(out_dir) + "/array.sbatch";
}
std::string slurm_merge_script_path(const std::string& out_dir) {
  return slurm_dir(out_dir) + "/merge.sbatch";
}

std::string render_slurm_array_script(const SlurmScriptOptions& o) {
  validate(o);
  const std::uint64_t tasks = slurm_array_tasks(o.shards, o.max_array_size);
  const std::string n = std::to_string(o.shards);
  const std::string t = std::to_string(tasks);
  std::ostringstream s;
  s << "#!/bin/bash\n";
  s << "#SBATCH --job-name=fsweep-" << o.name << '\n';
  s << "#SBATCH --array=0-" << tasks - 1 << '\n';
  s << "#SBATCH --cpus-per-task=" << o.cpus << '\n';
  resource_directives(s, o);
  if (!o.gres.empty()) s << "#SBATCH --gres=" << o.gres << '\n';
  s << "#SBATCH --output=" << escape_pattern(slurm_log_dir(o.out_dir)) << "/%A_%a.out\n";
  extra_directives(s, o);
  s << "#\n"
    << "# Written by `fsweep slurm`: sweep " << o.name << " in " << n << " shards over " << t
    << " array tasks. Array task t runs\n"
    << "# shards t, t+" << t << ", t+" << 2 * tasks << ", ... below " << n
    << " one after the other (fsweep run --shard i/" << n << ", which resumes a partly\n"
    << "# done shard), tries all of them and exits 1 if any failed. To redo some tasks only (ids below " << t
    << "):\n"
    << "#   sbatch --array=<ids, e.g. " << (tasks == 1 ? std::string("0") : "0," + std::to_string(tasks - 1))
    << "> " << slurm_array_script_path(o.out_dir) << '\n'
    << "# then merge: sbatch " << slurm_merge_script_path(o.out_dir) << "  (or: fsweep merge " << o.out_dir
    << ")\n\n";
  s << "set -u\n"
    << "shards=" << n << '\n'
    << "tasks=" << t << '\n'
    << "task=${SLURM_ARRAY_TASK_ID:-}\n"
    << "case \"$task\" in\n"
    << "  '' | *[!0-9]*) echo \"fsweep slurm: SLURM_ARRAY_TASK_ID is '$task', expected an array index\" >&2; "
       "exit 2 ;;\n"
    << "esac\n"
    << "task=$((10#$task))\n"
    << "if ((task >= tasks)); then\n"
    << "  echo \"fsweep slurm: array index $task is not below $tasks, the array size this script was written "
       "for\" "
       ">&2\n"
    << "  exit 2\n"
    << "fi\n"
    << "cd -- " << shell_quote(o.work_dir) << " || exit 2\n";
  setup_block(s, o, /*restore_nounset=*/true);
  s << "failed=0\n"
    << "for ((shard = task; shard < shards; shard += tasks)); do\n"
    << "  echo \"fsweep slurm: array task $task: shard $shard/$shards on $(hostname)\"\n"
    << "  " << shell_quote(o.fsweep) << " run " << shell_quote(o.sweep_file);
  for (const std::string& text : o.overrides) s << ' ' << shell_quote(text);
  s << " --out " << shell_quote(o.out_dir) << " --shard \"$shard/$shards\" \\\n"
    << "    --threads \"${SLURM_CPUS_PER_TASK:-1}\" --quiet\n"
    << "  rc=$?\n"
    << "  if ((rc != 0)); then\n"
    << "    echo \"fsweep slurm: shard $shard/$shards failed (exit $rc)\" >&2\n"
    << "    failed=$((failed + 1))\n"
    << "  fi\n"
    << "done\n"
    << "if ((failed > 0)); then\n"
    << "  echo \"fsweep slurm: array task $task: $failed shard(s) failed\" >&2\n"
    << "  exit 1\n"
    << "fi\n";
  return s.str();
}

std::string render_slurm_merge_script(const SlurmScriptOptions& o) {
  validate(o);
  std::ostringstream s;
  s << "#!/bin/bash\n";
  s << "#SBATCH --job-name=fsweep-" << o.name << "-merge\n";
  s << "#SBATCH --cpus-per-task=1\n";
  resource_directives(s, o);
  s << "#SBATCH --output=" << escape_pattern(slurm_log_dir(o.out_dir)) << "/merge_%j.out\n";
  extra_directives(s, o);
  s << "#\n"
    << "# Written by `fsweep slurm`: merges the " << o.shards << " shards of sweep " << o.name
    << " once every array task has ended\n"
    << "# (submitted with --dependency=afterany:<array job>, so it also runs after failures and then\n"
    << "# lists the missing runs and exits 1, or names a shard whose weight search did not finish and\n"
    << "# exits 2, writing nothing but the searches' joint status).\n\n";
  s << "cd -- " << shell_quote(o.work_dir) << " || exit 2\n";
  setup_block(s, o, /*restore_nounset=*/false);
  s << "exec " << shell_quote(o.fsweep) << " merge " << shell_quote(o.out_dir) << '\n';
  return s.str();
}

std::vector<std::string> slurm_array_submit_command(const std::string& out_dir) {
  return {"sbatch", "--parsable", slurm_array_script_path(out_dir)};
}

std::vector<std::string> slurm_merge_submit_command(const std::string& out_dir,
                                                    const std::string& array_job_id) {
  return {"sbatch", "--parsable", "--dependency=afterany:" + array_job_id, slurm_merge_script_path(out_dir)};
}

std::string shell_quote(const std::string& s) {
  const auto plain = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 ||
           std::string_view("_./:=%+,@-").find(c) != std::string_view::npos;
  };
  if (!s.empty() && std::all_of(s.begin(), s.end(), plain)) return s;
  std::string out = "'";
  for (const char c : s) {
    if (c == '\'') {
      out += "'\\''";
    } else {
      out += c;
    }
  }
  return out + "'";
}

std::string shell_command(const std::vector<std::string>& argv) {
  std::string out;
  for (const auto& a : argv) {
    if (!out.empty()) out += ' ';
    out += shell_quote(a);
  }
  return out;
}

std::optional<std::uint64_t> parse_max_array_size(const std::string& scontrol_config) {
  std::istringstream in(scontrol_config);
  std::string line;
  constexpr std::string_view kKey = "MaxArraySize";
  while (std::getline(in, line)) {
    std::string_view v(line);
    while (!v.empty() && std::isspace(static_cast<unsigned char>(v.front())) != 0) v.remove_prefix(1);
    if (!v.starts_with(kKey)) continue;
    v.remove_prefix(kKey.size());
    while (!v.empty() && (v.front() == ' ' || v.front() == '\t')) v.remove_prefix(1);
    if (v.empty() || v.front() != '=') continue;  // e.g. "MaxArraySizeX = ..."
    v.remove_prefix(1);
    while (!v.empty() && std::isspace(static_cast<unsigned char>(v.front())) != 0) v.remove_prefix(1);
    while (!v.empty() && std::isspace(static_cast<unsigned char>(v.back())) != 0) v.remove_suffix(1);
    std::uint64_t k = 0;
    const auto [ptr, ec] = std::from_chars(v.data(), v.data() + v.size(), k);
    if (ec != std::errc() || ptr != v.data() + v.size() || v.empty()) return std::nullopt;
    return k;
  }
  return std::nullopt;
}

std::optional<std::string> parse_sbatch_job_id(const std::string& sbatch_output) {
  std::string_view v(sbatch_output);
  while (!v.empty() && std::isspace(static_cast<unsigned char>(v.front())) != 0) v.remove_prefix(1);
  while (!v.empty() && std::isspace(static_cast<unsigned char>(v.back())) != 0) v.remove_suffix(1);
  const auto semi = v.find(';');
  if (semi != std::string_view::npos) v = v.substr(0, semi);
  if (v.empty() || !std::all_of(v.begin(), v.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return std::nullopt;
  return std::string(v);
}

}  // namespace sweep
}  // namespace fsweep
