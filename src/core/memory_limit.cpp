#include "core/memory_limit.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <utility>

#include "core/files.hpp"
#include "core/readable_number.hpp"

namespace fsweep {
inline namespace core {
namespace {

constexpr std::uint64_t kKiB = 1024;

/// The bytes of a size suffix (K, M, G, T, either case); 0 for any other character.
std::uint64_t suffix_bytes(char c) {
  switch (std::toupper(static_cast<unsigned char>(c))) {
    case 'K':
      return kKiB;
    case 'M':
      return kKiB * kKiB;
    case 'G':
      return kKiB * kKiB * kKiB;
    case 'T':
      return kKiB * kKiB * kKiB * kKiB;
    default:
      return 0;
  }
}

/// `text` as a whole decimal number (digits only); nullopt otherwise or beyond 64 bits.
std::optional<std::uint64_t> whole_number(std::string_view text) {
  std::uint64_t v = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
  return v;
}

/// `text` without leading and trailing whitespace (files end with a newline).
std::string_view trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r\n");
  return text.substr(first, last - first + 1);
}

/// `path` without its last component ("/a/b" -> "/a", "/a" -> ""): the parent cgroup.
std::string parent_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash);
}

/// The smallest limit among the files `file_name` in the cgroup folder `mount` + `path` and in
/// the folders above it up to `mount` (the effective limit of a cgroup is the smallest of its
/// ancestors'); files that are missing or say "max" do not count.
std::optional<MemoryLimit> smallest_cgroup_limit(const FileText& read, const std::string& mount,
                                                 std::string path, const std::string& file_name,
                                                 const std::string& version) {
  std::optional<MemoryLimit> smallest;
  while (!path.empty() && path.back() == '/') path.pop_back();
  for (;;) {
    std::string file = mount;
    file.append(path).append("/").append(file_name);
    if (const std::optional<std::string> text = read(file)) {
      if (const auto bytes = cgroup_limit_bytes(*text); bytes && (!smallest || *bytes < smallest->bytes)) {
        std::string source = version;
        source.append(" (").append(file).append(")");
        smallest = MemoryLimit{*bytes, std::move(source)};
      }
    }
    if (path.empty()) return smallest;
    path = parent_of(path);
  }
}

}  // namespace

std::optional<std::uint64_t> parse_memory_size(std::string_view text) {
  std::uint64_t unit = 1;
  if (!text.empty() && suffix_bytes(text.back()) != 0) {
    unit = suffix_bytes(text.back());
    text.remove_suffix(1);
  }
  const auto point = text.find('.');
  const std::optional<std::uint64_t> whole = whole_number(text.substr(0, point));
  if (!whole || *whole > std::numeric_limits<std::uint64_t>::max() / unit) return std::nullopt;
  std::uint64_t bytes = *whole * unit;
  if (point != std::string_view::npos) {
    const std::string_view digits = text.substr(point + 1);
    if (unit == 1 || digits.empty() || digits.find_first_not_of("0123456789") != std::string_view::npos) {
      return std::nullopt;  // a count of bytes is whole
    }
    double fraction = 0.0;  // "0.<digits>": below 1, so fraction x unit fits in 64 bits
    const std::string decimal = "0." + std::string(digits);
    (void)std::from_chars(decimal.data(), decimal.data() + decimal.size(), fraction);
    const auto part = static_cast<std::uint64_t>(std::floor(fraction * static_cast<double>(unit)));
    if (bytes > std::numeric_limits<std::uint64_t>::max() - part) return std::nullopt;
    bytes += part;
  }
  if (bytes == 0) return std::nullopt;
  return bytes;
}

std::string readable_memory_size(std::uint64_t bytes) {
  constexpr std::array<const char*, 5> kUnits{"B", "KiB", "MiB", "GiB", "TiB"};
  auto value = static_cast<double>(bytes);
  std::size_t unit = 0;
  while (value >= static_cast<double>(kKiB) && unit + 1 < kUnits.size()) {
    value /= static_cast<double>(kKiB);
    ++unit;
  }
  return readable_number(value, 3) + " " + kUnits[unit];
}

std::optional<std::uint64_t> meminfo_total_bytes(std::string_view meminfo) {
  constexpr std::string_view kKey = "MemTotal:";
  for (std::size_t at = 0; at < meminfo.size();) {
    const auto end = std::min(meminfo.find('\n', at), meminfo.size());
    const std::string_view line = meminfo.substr(at, end - at);
    at = end + 1;
    if (!line.starts_with(kKey)) continue;
    const std::string_view value = trimmed(line.substr(kKey.size()));
    if (!value.ends_with("kB")) return std::nullopt;  // the kernel writes "MemTotal: N kB"
    const std::optional<std::uint64_t> kib = whole_number(trimmed(value.substr(0, value.size() - 2)));
    if (!kib || *kib > std::numeric_limits<std::uint64_t>::max() / kKiB) return std::nullopt;
    return *kib * kKiB;
  }
  return std::nullopt;
}

std::optional<std::uint64_t> cgroup_limit_bytes(std::string_view file) {
  return whole_number(trimmed(file));  // "max" is not a number
}

CgroupPaths parse_proc_cgroup(std::string_view proc_self_cgroup) {
  CgroupPaths paths;
  for (std::size_t at = 0; at < proc_self_cgroup.size();) {
    const auto end = std::min(proc_self_cgroup.find('\n', at), proc_self_cgroup.size());
    const std::string_view line = proc_self_cgroup.substr(at, end - at);
    at = end + 1;
    // "hierarchy-id:controller-list:path"; the path may itself hold colons.
    const auto first = line.find(':');
    const auto second = first == std::string_view::npos ? first : line.find(':', first + 1);
    if (second == std::string_view::npos) continue;
    const std::string_view id = line.substr(0, first);
    const std::string_view controllers = line.substr(first + 1, second - first - 1);
    const std::string path(line.substr(second + 1));
    if (id == "0" && controllers.empty()) {
      paths.v2 = path;
      continue;
    }
    for (std::size_t c = 0; c <= controllers.size();) {
      const auto comma = std::min(controllers.find(',', c), controllers.size());
      if (controllers.substr(c, comma - c) == "memory") paths.v1_memory = path;
      c = comma + 1;
    }
  }
  return paths;
}

std::optional<MemoryLimit> default_memory_limit(const FileText& read) {
  std::optional<MemoryLimit> limit;
  if (const auto meminfo = read("/proc/meminfo")) {
    if (const auto total = meminfo_total_bytes(*meminfo)) {
      limit = MemoryLimit{*total, "the machine's memory (MemTotal in /proc/meminfo)"};
    }
  }
  const CgroupPaths paths = parse_proc_cgroup(read("/proc/self/cgroup").value_or("0::/\n"));
  // cgroup v1 writes a number near 2^63 for "no limit": only a limit below the machine's counts.
  // A v2 limit is a limit (no limit reads "max").
  const std::optional<MemoryLimit> v2 = smallest_cgroup_limit(
      read, "/sys/fs/cgroup", paths.v2.empty() ? "/" : paths.v2, "memory.max", "cgroup v2");
  const std::optional<MemoryLimit> v1 =
      smallest_cgroup_limit(read, "/sys/fs/cgroup/memory", paths.v1_memory.empty() ? "/" : paths.v1_memory,
                            "memory.limit_in_bytes", "cgroup v1");
  if (v2 && (!limit || v2->bytes < limit->bytes)) limit = v2;
  if (v1 && limit && v1->bytes < limit->bytes) limit = v1;
  return limit;
}

std::optional<MemoryLimit> default_memory_limit() { return default_memory_limit(read_file); }

std::optional<std::uint64_t> statm_resident_bytes(std::string_view statm, std::uint64_t page_bytes) {
  // "size resident shared text lib data dt", in pages.
  const auto first = statm.find(' ');
  if (first == std::string_view::npos) return std::nullopt;
  const std::string_view rest = statm.substr(first + 1);
  const std::optional<std::uint64_t> pages = whole_number(rest.substr(0, rest.find(' ')));
  if (!pages || page_bytes == 0 || *pages > std::numeric_limits<std::uint64_t>::max() / page_bytes) {
    return std::nullopt;
  }
  return *pages * page_bytes;
}

std::optional<std::uint64_t> resident_memory_bytes() {
  // open, read, close: no stream, no allocation (the memory guard reads it often).
  const int fd = ::open("/proc/self/statm", O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  std::array<char, 128> buf{};
  const ssize_t n = ::read(fd, buf.data(), buf.size());
  ::close(fd);
  if (n <= 0) return std::nullopt;
  const long page = ::sysconf(_SC_PAGESIZE);
  return statm_resident_bytes(std::string_view(buf.data(), static_cast<std::size_t>(n)),
                              page > 0 ? static_cast<std::uint64_t>(page) : 0);
}

}  // namespace core
}  // namespace fsweep
