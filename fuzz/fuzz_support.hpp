#pragma once
/// @file fuzz_support.hpp
/// What the fuzz targets share: the input written to a file (the parsers read files, as the
/// CLI does) and the rule every target checks: a parser returns, or throws ConfigError; any other
/// exception, a crash or a sanitizer report is a bug.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "core/config_error.hpp"

namespace fsweep::fuzz {

/// A scratch directory for this process, removed at exit.
class ScratchDir {
 public:
  ScratchDir()
      : path_((std::filesystem::temp_directory_path() / ("fsweep_fuzz_" + std::to_string(::getpid())))
                  .string()) {
    std::filesystem::create_directories(path_);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  std::string path_;
};

/// The process's scratch directory.
inline const std::string& scratch_dir() {
  static const ScratchDir dir;
  return dir.path();
}

/// Writes `bytes` to `<scratch>/<name>` (replacing it) and returns the path.
inline std::string write_scratch(const std::string& name, std::string_view bytes) {
  const std::string path = scratch_dir() + "/" + name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return path;
}

/// The input as a string view.
inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast): the fuzzer's bytes, read as chars
  return {reinterpret_cast<const char*>(data), size};
}

/// Runs `parse`; a ConfigError (the promised clear error) is an expected outcome.
template <typename F>
void accept_clear_errors(F&& parse) {
  try {
    parse();
  } catch (const ConfigError&) {  // NOLINT(bugprone-empty-catch): refusing bad input is correct
  }
}

}  // namespace fsweep::fuzz
