#pragma once
/// @file sweep_test_files.hpp
/// Scratch files for the sweep tests: fresh temp directories and whole-file reads and writes.

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fsweep::testing {

/// A fresh, empty directory <tmp>/fsweep_<tag>_<name>_<pid> (removed first if it exists).
inline std::string fresh_dir(const std::string& tag, const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("fsweep_" + tag + "_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

/// The whole file as bytes ("" when it cannot be read).
inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Replaces the file's contents with `text`.
inline void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

}  // namespace fsweep::testing
