#pragma once
// Where the tests find ../shared/data (the real TUM frames), and a skip when it is absent.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace hrgbd::test {

/** $HRGBD_SHARED_DATA, else <source>/../shared/data; "" if neither exists. */
inline std::string sharedDataDir() {
  if (const char* env = std::getenv("HRGBD_SHARED_DATA"); env && std::filesystem::is_directory(env))
    return env;
  const auto p = std::filesystem::path(HRGBD_SOURCE_DIR) / ".." / "shared" / "data";
  return std::filesystem::is_directory(p) ? std::filesystem::canonical(p).string() : "";
}

/** A fresh, empty temporary folder for one test, private to this process (two checkouts or two
 * ctest runs on one machine never share it). */
inline std::string tempDir(const std::string& name) {
  const auto p = std::filesystem::temp_directory_path() /
                 ("hrgbd_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(p);
  std::filesystem::create_directories(p);
  return p.string();
}

/** A tempDir() that is removed when the test program exits normally, for tests that write large
 * files (recordings of tens of MB). */
inline std::string scratchDir(const std::string& name) {
  struct Cleanup {
    std::vector<std::string> dirs;
    ~Cleanup() {
      for (const auto& d : dirs) std::filesystem::remove_all(d);
    }
  };
  static Cleanup cleanup;
  cleanup.dirs.push_back(tempDir(name));
  return cleanup.dirs.back();
}

}  // namespace hrgbd::test

/** Skips the test, saying why, if ../shared/data is absent. Defines `data` (a std::string). */
#define HRGBD_REQUIRE_SHARED_DATA(data)                  \
  const std::string data = hrgbd::test::sharedDataDir(); \
  if (data.empty())                                      \
  GTEST_SKIP() << "../shared/data not found (set HRGBD_SHARED_DATA): real-data test skipped"
