#pragma once
// Running the apps as the user runs them (tests/regression/App*_test.cpp).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "TestData.h"

extern char** environ;

namespace hrgbd::test {

/** What a run of an app did. */
struct Run {
  int code = -1;
  std::string out, err;
};

/** The whole content of a file ("" if it cannot be read). */
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

/** Runs `app` (a name in <build>/apps) with `args` (shell words) and captures its output. A run
 * that should have been refused but starts the job is stopped after two minutes (exit 124). */
inline Run runApp(const std::string& app, const std::string& args) {
  static int runs = 0;  // ctest runs the tests in parallel processes: one folder per run
  const std::filesystem::path dir =
      tempDir("cli_capture_" + std::to_string(getpid()) + "_" + std::to_string(runs++));
  const auto cmd = "timeout 120 " + std::string(HRGBD_BINARY_DIR) + "/apps/" + app + " " + args +
                   " > " + (dir / "out").string() + " 2> " + (dir / "err").string() +
                   " < /dev/null";
  const int status = std::system(cmd.c_str());
  Run r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(dir / "out");
  r.err = slurp(dir / "err");
  std::filesystem::remove_all(dir);
  return r;
}

/** Expects exit 2 and "<app>: error: ..." on stderr, nothing on stdout. */
inline Run expectRefused(const std::string& app, const std::string& args) {
  const auto r = runApp(app, args);
  EXPECT_EQ(r.code, 2) << app << " " << args << "\n" << r.out << r.err;
  EXPECT_EQ(r.err.rfind(app + ": error: ", 0), 0u) << app << " " << args << "\n" << r.err;
  EXPECT_NE(r.err.find(app + " --help"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << app << " " << args << "\n" << r.out;
  return r;
}

/** Expects exit 1 (a runtime error, not a command-line one) and "<app>: error: ..." on stderr
 * containing every one of `parts`. */
inline Run expectFailure(const std::string& app, const std::string& args,
                         const std::vector<std::string>& parts) {
  const auto r = runApp(app, args);
  EXPECT_EQ(r.code, 1) << app << " " << args << "\n" << r.out << r.err;
  EXPECT_NE(r.err.find(app + ": error: "), std::string::npos) << app << " " << args << "\n"
                                                              << r.err;
  EXPECT_EQ(r.err.find(" --help"), std::string::npos) << "not a command-line error: " << r.err;
  for (const auto& p : parts)
    EXPECT_NE(r.err.find(p), std::string::npos) << app << " " << args << "\n" << r.err;
  return r;
}

/** A TUM folder of `frames` simulated frames at `dir`; returns it. */
inline std::string makeTumFolder(const std::filesystem::path& dir, int frames = 3) {
  const auto r = runApp("rgbd-simulate",
                        "-q --scene wall -n " + std::to_string(frames) + " --tum " + dir.string());
  EXPECT_EQ(r.code, 0) << r.err;
  return dir.string();
}

/** The lines of `text` that are neither empty nor comments. */
inline std::vector<std::string> dataLines(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);)
    if (!l.empty() && l[0] != '#') out.push_back(l);
  return out;
}

/** A long input made fast, at `dir`: three simulated frames listed 3,000 times, 1/30 s apart. */
inline std::string makeLongTumFolder(const std::filesystem::path& dir) {
  const auto tum = makeTumFolder(dir);
  for (const auto* list : {"rgb.txt", "depth.txt"}) {
    const auto lines = dataLines(slurp(dir / list));
    std::ofstream out(dir / list);
    for (int k = 0; k < 3000; ++k)
      out << std::fixed << 1.0 + k / 30.0 << lines[k % 3].substr(lines[k % 3].find(' ')) << "\n";
  }
  return tum;
}

/** The path of app `name` in <build>/apps. */
inline std::string app(const std::string& name) {
  return std::string(HRGBD_BINARY_DIR) + "/apps/" + name;
}

/** Starts `argv` with stdout and stderr to files in `dir`; returns its process id. */
inline pid_t spawn(const std::vector<std::string>& argv, const std::filesystem::path& dir) {
  posix_spawn_file_actions_t io;
  posix_spawn_file_actions_init(&io);
  posix_spawn_file_actions_addopen(&io, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&io, 1, (dir / "out").c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_addopen(&io, 2, (dir / "err").c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = -1;
  EXPECT_EQ(posix_spawn(&pid, args[0], &io, nullptr, args.data(), environ), 0);
  posix_spawn_file_actions_destroy(&io);
  return pid;
}

/** Waits (at most ~60 s) until `ready()` holds or the process has ended; true if it holds. */
template <class F>
inline bool waitFor(pid_t pid, F ready) {
  for (int k = 0; k < 6000; ++k) {
    if (ready()) return true;
    if (waitpid(pid, nullptr, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

/** The process catches SIGINT: its handler is installed (the signal would end it otherwise). */
inline bool catchesSigint(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("SigCgt:", 0) == 0) return std::stoull(line.substr(7), nullptr, 16) & 0x2;
  return false;
}

/** The exit code of `pid` (-1 if a signal ended it). */
inline int exitCode(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace hrgbd::test
