#pragma once
/// @file sweep_test_files.hpp
/// Scratch files for the sweep tests: fresh temp directories and whole-file reads and writes;
/// a SIGINT sent when the files say so (the Ctrl-C tests).

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace fsweep::testing {

/// The directories fresh_dir() made, removed when the test program has run its tests and every
/// one passed; a failed program leaves them for a look.
class ScratchDirs : public ::testing::Environment {
 public:
  static void add(const std::filesystem::path& dir) { made().push_back(dir); }
  void TearDown() override {
    if (!::testing::UnitTest::GetInstance()->Passed()) return;
    for (const std::filesystem::path& dir : made()) {
      std::error_code ignored;  // a directory a test removed itself
      std::filesystem::remove_all(dir, ignored);
    }
  }

 private:
  static std::vector<std::filesystem::path>& made() {
    static std::vector<std::filesystem::path> dirs;
    return dirs;
  }
};
inline ::testing::Environment* const kScratchDirs = ::testing::AddGlobalTestEnvironment(new ScratchDirs);

/// A fresh, empty directory <tmp>/fsweep_<tag>_<name>_<pid> (removed first if it exists; removed
/// after the program's tests if all passed, ScratchDirs).
inline std::string fresh_dir(const std::string& tag, const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("fsweep_" + tag + "_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  ScratchDirs::add(dir);
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

/// Sends this process SIGINT `signals` times, back to back (as timeout(1) signals the process
/// and its group), once `ready()` holds (polled every 0.5 ms; after 60 s without it, anyway),
/// from a thread started by the constructor. Meanwhile SIGINT's own handler ignores it,
/// so a late signal (after the code under test restored its handlers) does not end the test;
/// join() waits for the thread and restores the previous handler.
class InterruptWhen {
 public:
  explicit InterruptWhen(std::function<bool()> ready, int signals = 1) {
    struct sigaction ignore {};
    ignore.sa_handler = [](int) {};
    ::sigaction(SIGINT, &ignore, &previous_);
    thread_ = std::thread([ready = std::move(ready), signals] {
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
      while (std::chrono::steady_clock::now() < deadline && !ready()) {
        std::this_thread::sleep_for(std::chrono::microseconds(500));
      }
      for (int k = 0; k < signals; ++k) {
        ::kill(::getpid(), SIGINT);
        std::this_thread::sleep_for(std::chrono::milliseconds(2));  // delivered one by one
      }
    });
  }
  InterruptWhen(const InterruptWhen&) = delete;
  InterruptWhen& operator=(const InterruptWhen&) = delete;
  ~InterruptWhen() { join(); }
  void join() {
    if (!thread_.joinable()) return;
    thread_.join();
    ::sigaction(SIGINT, &previous_, nullptr);
  }

 private:
  struct sigaction previous_ {};
  std::thread thread_;
};

}  // namespace fsweep::testing
