#pragma once
/// @file shard_dirs.hpp
/// The folders of a sharded sweep's output directory: `fsweep run --shard i/N` writes shard i's
/// results into DIR/shard-<i>-of-<N>/ (sweep_runner.hpp, Sharding), `fsweep merge` joins them
/// (merge.hpp), and the output-directory checks and the report commands recognize them. One
/// reader of the name for all of them.

#include <cstdint>
#include <string>
#include <vector>

namespace fsweep {
inline namespace core {

/// The folder of shard `index` of `count` in a sweep's output directory: "shard-<i>-of-<n>".
[[nodiscard]] std::string shard_dir_name(std::uint64_t index, std::uint64_t count);

/// A shard folder found in a sweep's output directory.
struct ShardDir {
  std::uint64_t index = 0;
  std::uint64_t count = 0;
  std::string path;
};

/// The folders of `dir` named as shard_dir_name() names them (any i and n that are whole
/// numbers), ordered by n, then i; empty when there are none or `dir` cannot be read.
[[nodiscard]] std::vector<ShardDir> shard_dirs(const std::string& dir);

}  // namespace core
}  // namespace fsweep
