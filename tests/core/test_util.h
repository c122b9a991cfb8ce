// Helpers for tests that write files: a fresh temporary directory per test, removed afterwards.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "core/data_dir.h"
#include "core/error.h"

namespace vigil::testing {

class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() / ("vigil_test_" + std::string(info->test_suite_name()) +
                                                      "_" + info->name() + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  const std::filesystem::path& path() const { return path_; }
  std::string File(const std::string& name, const std::string& content) const {
    const auto p = path_ / name;
    std::ofstream(p) << content;
    return p.string();
  }

 private:
  std::filesystem::path path_;
};

// Runs `f` and returns the InputError message it throws ("" if none).
template <class F>
std::string InputErrorOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// VIGIL_DATA set to `value` (unset: nullptr) for one test, restored after it.
class ScopedDataDir {
 public:
  explicit ScopedDataDir(const char* value) {
    if (const char* old = std::getenv(kDataDirVariable)) old_ = old, had_ = true;
    value ? setenv(kDataDirVariable, value, 1) : unsetenv(kDataDirVariable);
  }
  ~ScopedDataDir() { had_ ? setenv(kDataDirVariable, old_.c_str(), 1) : unsetenv(kDataDirVariable); }
  ScopedDataDir(const ScopedDataDir&) = delete;
  ScopedDataDir& operator=(const ScopedDataDir&) = delete;

 private:
  std::string old_;
  bool had_ = false;
};

}  // namespace vigil::testing
