#pragma once
/// @file memory_limit.hpp
/// How much memory the process may use, and how much it uses: the limit `fsweep run
/// --max-memory` sets or, by default, the one its cgroup sets (a container's, a Slurm job's),
/// else the machine's memory; and the process's resident memory. The exact weight search's
/// memory guard (memory_watch.hpp) compares the two. The readers take file contents as text, so
/// tests feed them strings.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace fsweep {
inline namespace core {

/// A memory limit and where it came from.
struct MemoryLimit {
  std::uint64_t bytes = 0;
  /// "--max-memory", "cgroup v2 (/sys/fs/cgroup/.../memory.max)", "cgroup v1 (...)" or
  /// "the machine's memory (MemTotal in /proc/meminfo)".
  std::string source;
};

/// A size as `--max-memory` takes it: a number of bytes ("1073741824"), or a number, possibly
/// with a fraction, followed by K, M, G or T (either case; powers of 1024, as Slurm's `--mem`
/// reads them; a fraction of the unit is rounded down to whole bytes): "512M", "1.5G", "4g".
/// Nullopt for anything else, for zero, for a fraction of a byte and for sizes beyond 2^64 - 1
/// bytes.
[[nodiscard]] std::optional<std::uint64_t> parse_memory_size(std::string_view text);

/// `bytes` for people, in the largest of B, KiB, MiB, GiB, TiB that leaves at least 1, to three
/// significant digits: "512 MiB", "1.5 GiB", "3.62 GiB".
[[nodiscard]] std::string readable_memory_size(std::uint64_t bytes);

/// MemTotal of /proc/meminfo's text, in bytes; nullopt when it has no such line.
[[nodiscard]] std::optional<std::uint64_t> meminfo_total_bytes(std::string_view meminfo);

/// The limit a cgroup file holds: cgroup v2's memory.max ("max": none) or v1's
/// memory.limit_in_bytes (a number; without a limit, a number near 2^63). Nullopt for "max" and
/// for text that is not a whole number (surrounding whitespace allowed).
[[nodiscard]] std::optional<std::uint64_t> cgroup_limit_bytes(std::string_view file);

/// The process's cgroup paths, from /proc/self/cgroup's text: the v2 one ("0::/path") and the
/// v1 memory controller's ("4:memory:/path"); empty where it has none.
struct CgroupPaths {
  std::string v2;
  std::string v1_memory;
};
[[nodiscard]] CgroupPaths parse_proc_cgroup(std::string_view proc_self_cgroup);

/// Reads a file's text; nullopt when it cannot be read (missing, no permission).
using FileText = std::function<std::optional<std::string>(const std::string& path)>;

/// The limit the process is under when `--max-memory` is not given: the smallest memory limit
/// of its cgroup and of the cgroups above it (cgroup v2's memory.max under /sys/fs/cgroup, v1's
/// memory.limit_in_bytes under /sys/fs/cgroup/memory; the process's own cgroup is read from
/// /proc/self/cgroup), where that is below the machine's memory; else the machine's memory
/// (MemTotal in /proc/meminfo). Nullopt when neither can be read. `read` reads the files (tests
/// give their own).
[[nodiscard]] std::optional<MemoryLimit> default_memory_limit(const FileText& read);

/// default_memory_limit() of this machine's files.
[[nodiscard]] std::optional<MemoryLimit> default_memory_limit();

/// The resident set size in bytes given /proc/self/statm's text (its second field, in pages of
/// `page_bytes`); nullopt when it does not parse.
[[nodiscard]] std::optional<std::uint64_t> statm_resident_bytes(std::string_view statm,
                                                                std::uint64_t page_bytes);

/// The process's resident memory now (/proc/self/statm; a few microseconds), nullopt when it
/// cannot be read.
[[nodiscard]] std::optional<std::uint64_t> resident_memory_bytes();

}  // namespace core
}  // namespace fsweep
