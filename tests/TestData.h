#pragma once
// Where the tests find ../shared/data (the real TUM frames), and a skip when it is absent.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace hrgbd::test {

/** $HRGBD_SHARED_DATA, else <source>/../shared/data; "" if neither exists. */
inline std::string sharedDataDir() {
  if (const char* env = std::getenv("HRGBD_SHARED_DATA"); env && std::filesystem::is_directory(env))
    return env;
  const auto p = std::filesystem::path(HRGBD_SOURCE_DIR) / ".." / "shared" / "data";
  return std::filesystem::is_directory(p) ? std::filesystem::canonical(p).string() : "";
}

/** Temporary folders removed when the test program exits normally: every one marked `always`,
 * the others only when every test passed (a failure's files stay to be looked at). */
struct TempDirs {
  std::vector<std::pair<std::string, bool>> dirs;  //!< (folder, always)
  ~TempDirs() {
    const bool passed = ::testing::UnitTest::GetInstance()->Passed();
    std::error_code ignored;
    for (const auto& [d, always] : dirs)
      if (always || passed) std::filesystem::remove_all(d, ignored);
  }
  static std::string add(const std::string& name, bool always) {
    static TempDirs all;
    const auto p = std::filesystem::temp_directory_path() /
                   ("hrgbd_test_" + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(p);
    std::filesystem::create_directories(p);
    all.dirs.emplace_back(p.string(), always);
    return p.string();
  }
};

/** A fresh, empty temporary folder for one test, private to this process (two checkouts or two
 * ctest runs on one machine never share it); removed at exit if every test passed. */
inline std::string tempDir(const std::string& name) { return TempDirs::add(name, false); }

/** A tempDir() that is removed at exit in any case, for tests that write large files
 * (recordings of tens of MB). */
inline std::string scratchDir(const std::string& name) { return TempDirs::add(name, true); }

/** The message of the std::runtime_error `f` throws ("" if none). */
template <class F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace hrgbd::test

/** Skips the test, saying why, if ../shared/data is absent. Defines `data` (a std::string). */
#define HRGBD_REQUIRE_SHARED_DATA(data)                  \
  const std::string data = hrgbd::test::sharedDataDir(); \
  if (data.empty())                                      \
  GTEST_SKIP() << "../shared/data not found (set HRGBD_SHARED_DATA): real-data test skipped"
