// What the apps print while they work, through the real binaries: the steps after the last frame
// each on a line of its own (on a terminal and in a log), the benchmark's run count and its
// partial results when interrupted, the vocabulary's stages and the INI lines that use it, the
// simulator's scene and files. No timing is asserted: only that times are there.
#include <signal.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "AppRun.h"

namespace {

namespace fs = std::filesystem;
using hrgbd::test::app;
using hrgbd::test::exitCode;
using hrgbd::test::runApp;
using hrgbd::test::slurp;
using hrgbd::test::spawn;
using hrgbd::test::waitFor;

const std::string kDesk = std::string(HRGBD_SOURCE_DIR) + "/rawlogs/desk_near.rawlog";

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/** `text` has a line matching `pattern` (ECMAScript, whole line). */
bool hasLine(const std::string& text, const std::string& pattern) {
  const std::regex re(pattern);
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) {
    if (!l.empty() && l.back() == '\r') l.pop_back();  // a terminal's line ends
    if (std::regex_match(l, re)) return true;
  }
  return false;
}

const std::string kTime = R"( \.\.\. [0-9.]+ s)";  // a timed step's end: " ... 1.2 s"

}  // namespace

// ---- playback: the steps after the last frame ------------------------------------------------

TEST(AppProgress, StepsAfterTheLastFrameEachPrintALineWithTheirTime) {
  const fs::path dir = hrgbd::test::tempDir("progress_steps");
  const auto out = [&](const std::string& f) { return (dir / f).string(); };
  const auto r = runApp("hybrid-rgbd-odometry", "--slam -i " + kDesk + " -t " + out("t.txt") +
                                                    " --map-ply " + out("m.ply") + " --graph " +
                                                    out("g.graph") + " --csv " + out("f.csv"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find('\r'), std::string::npos) << "whole lines in a file: " << r.err;
  EXPECT_EQ(r.out.find('\r'), std::string::npos) << r.out;
  EXPECT_TRUE(contains(r.err, "20 frames in ")) << r.err;
  // in order, each with its time
  std::size_t at = 0;
  for (const std::string& step :
       {"SLAM: last loop searches and final optimisation" + kTime,
        std::string("SLAM: [0-9]+ nodes .*"), "SLAM: outputs moved to the optimised poses" + kTime,
        "trajectory \\(SLAM, optimised\\): " + out("t.txt") + kTime, "CSV: " + out("f.csv") + kTime,
        "map \\(PLY, [0-9]+ points\\): " + out("m.ply") + kTime,
        "pose graph \\(MRPT text format\\): " + out("g.graph") + kTime}) {
    std::smatch m;
    const std::string rest = r.out.substr(at);
    ASSERT_TRUE(std::regex_search(rest, m, std::regex("(^|\n)" + step + "\n"))) << step << "\n"
                                                                                << r.out;
    at += static_cast<std::size_t>(m.position(0) + m.length(0)) - 1;
  }
}

TEST(AppProgress, OnATerminalTheProgressLineEndsBeforeTheStepsAndCountsThem) {
  // stdout and stderr on one terminal (script(1) gives the run a pseudo-terminal): the SLAM
  // steps were printed onto the progress line ("... 0.1 s leftSLAM: ...")
  if (std::system("command -v script > /dev/null") != 0) GTEST_SKIP() << "no script(1)";
  const fs::path dir = hrgbd::test::tempDir("progress_terminal");
  const auto cmd = app("hybrid-rgbd-odometry") + " --slam -i " + kDesk + " -t " +
                   (dir / "t.txt").string() + " --map-ply " + (dir / "m.ply").string();
  const auto shell =
      "script -qec '" + cmd + "' /dev/null < /dev/null > " + (dir / "tty").string() + " 2>&1";
  ASSERT_EQ(std::system(shell.c_str()), 0) << slurp(dir / "tty");
  const auto tty = slurp(dir / "tty");
  EXPECT_TRUE(std::regex_search(tty, std::regex("\r[^\n]"))) << "redrawn in place: " << tty;
  EXPECT_TRUE(contains(tty, " left + final steps")) << tty;
  const auto step = tty.find("SLAM: last loop searches");
  ASSERT_NE(step, std::string::npos) << tty;
  ASSERT_GT(step, 0u);
  EXPECT_EQ(tty[step - 1], '\n') << "a line of its own: " << tty.substr(0, step + 40);
  const auto last_redraw = tty.rfind('\r', tty.rfind("20 frames in "));
  EXPECT_LT(last_redraw, step);
  EXPECT_TRUE(hasLine(tty, "SLAM: last loop searches and final optimisation" + kTime)) << tty;
}

// ---- rgbd-benchmark: run count, time left, partial results -----------------------------------

TEST(AppProgress, BenchmarkCountsRunsAndAnInterruptWritesTheFinishedOnesAsPartial) {
  const fs::path dir = hrgbd::test::tempDir("progress_benchmark");
  // the bundled desk (20 frames), then a long input: interrupted while it runs
  const auto tum = hrgbd::test::makeLongTumFolder(dir / "long");
  std::ofstream(dir / "b.ini") << "[Benchmark]\nmethods = rgb_only\nsim_scenes =\n"
                               << "real_sequences = " << kDesk << " " << tum << "\n";
  const fs::path run = dir / "run";
  fs::create_directories(run);
  const auto pid = spawn({app("rgbd-benchmark"), "-c", (dir / "b.ini").string()}, run);
  // stdout is a file: each line is there as the run ends (it was held back until the exit)
  const bool first = waitFor(pid, [&] { return contains(slurp(run / "out"), "run 1 of 2: "); });
  ASSERT_TRUE(first) << slurp(run / "out") << slurp(run / "err");
  kill(pid, SIGTERM);
  EXPECT_EQ(exitCode(pid), 143) << slurp(run / "err");
  const auto out = slurp(run / "out");
  EXPECT_TRUE(hasLine(out, "run 1 of 2: real/desk_near +rgb_only .* registered, .*; .* left"))
      << out;
  EXPECT_TRUE(contains(out, "partial results (terminated (SIGTERM) after 1 of 2 runs): ")) << out;
  EXPECT_TRUE(contains(slurp(run / "err"), "rgbd-benchmark: terminated (SIGTERM): stopped"));
  const auto md = slurp(dir / "benchmark" / "results_partial.md");
  EXPECT_EQ(md.rfind("# Benchmark results (PARTIAL)", 0), 0u) << md;
  EXPECT_TRUE(contains(md, "terminated (SIGTERM) after 1 of 2 runs")) << md;
  EXPECT_TRUE(contains(md, "| real/desk_near |")) << md;
  EXPECT_FALSE(contains(md, "| real/long |")) << md;
  EXPECT_EQ(hrgbd::test::dataLines(slurp(dir / "benchmark" / "results_partial.csv")).size(), 2u);
  EXPECT_FALSE(fs::exists(dir / "benchmark" / "results.md"));
  EXPECT_FALSE(fs::exists(dir / "benchmark" / "results.csv"));

  // a benchmark that finishes replaces them with the whole results
  const auto r =
      runApp("rgbd-benchmark", "-q -c " + (dir / "b.ini").string() + " --real-sequences " + kDesk);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(hasLine(r.out, "run 1 of 1: real/desk_near .*")) << r.out;
  EXPECT_TRUE(fs::exists(dir / "benchmark" / "results.md"));
  EXPECT_FALSE(fs::exists(dir / "benchmark" / "results_partial.md"));
  EXPECT_FALSE(fs::exists(dir / "benchmark" / "results_partial.csv"));
}

TEST(AppProgress, BenchmarkQuickPresetRunsNearSweepsIntoItsOwnFolder) {
  const fs::path dir = hrgbd::test::tempDir("progress_quick");
  // without --quick: near and far, two motions (4 sequences); the preset keeps the near sweep
  std::ofstream(dir / "b.ini") << "[Benchmark]\nmethods = rgb_only\nsim_scenes = texture\n"
                               << "sim_far = true\nsim_motions = sweep loop\nsim_frames = 3\n"
                               << "real_sequences =\n";
  const auto r =
      runApp("rgbd-benchmark", "-q --quick --methods rgb_only -c " + (dir / "b.ini").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(hasLine(r.out, "run 1 of 1: sim/texture_near/sweep +rgb_only .*")) << r.out;
  EXPECT_TRUE(fs::exists(dir / "benchmark_quick" / "results.md"));
  EXPECT_FALSE(fs::exists(dir / "benchmark"));
}

// ---- rgbd-vocabulary and rgbd-simulate ---------------------------------------------------------

TEST(AppProgress, VocabularyShowsItsStagesAndTheIniLinesThatUseIt) {
  const fs::path dir = hrgbd::test::tempDir("progress_vocabulary");
  const auto vocabulary = (dir / "v.txt").string();
  // two places: the desk and a textured wall
  auto r = runApp("rgbd-simulate", "-q --scene texture -n 3 --tum " + (dir / "wall").string());
  ASSERT_EQ(r.code, 0) << r.err;
  const fs::path here = fs::current_path();
  fs::current_path(dir);  // a relative output: the INI line gives it in full
  r = runApp("rgbd-vocabulary", "--words 500 --every 1 -o v.txt wall " + kDesk);
  fs::current_path(here);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(hasLine(r.err, "seeding: 500 words in .*")) << r.err;
  EXPECT_TRUE(hasLine(r.err, "k-majority: [0-9]+ rounds in .*")) << r.err;
  const auto ini = r.out.find("[Slam]\nvocabulary = " + vocabulary + "\n");
  ASSERT_NE(ini, std::string::npos) << r.out;
  // the lines as printed, in an INI file, give the SLAM mode this vocabulary
  std::ofstream(dir / "c.ini") << r.out.substr(ini);
  r = runApp("hybrid-rgbd-odometry", "-q --slam -n 5 -c " + (dir / "c.ini").string() + " -i " +
                                         kDesk + " -t " + (dir / "t.txt").string());
  EXPECT_EQ(r.code, 0) << r.err;
  fs::remove(vocabulary);
  r = runApp("hybrid-rgbd-odometry", "-q --slam -n 5 -c " + (dir / "c.ini").string() + " -i " +
                                         kDesk + " -t " + (dir / "t.txt").string());
  EXPECT_NE(r.code, 0) << "the INI's vocabulary is the one read";
}

TEST(AppProgress, SimulatorNamesTheSceneAsAskedAndTheFilesItWrote) {
  const fs::path dir = hrgbd::test::tempDir("progress_simulate");
  const auto rawlog = (dir / "d.rawlog").string(), tum = (dir / "seq").string();
  const auto r =
      runApp("rgbd-simulate", "-q --scene desk -n 2 -o " + rawlog + " --images png --tum " + tum);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(hasLine(r.out,
                      "rendered 2 frames of scene desk \\(near, ~1 m\\), median "
                      "[0-9]+\\.[0-9] ms/frame \\([0-9]+\\.[0-9] frames/s\\)"))
      << r.out;
  for (const auto& f :
       {rawlog, (dir / "d_groundtruth.txt").string(), (dir / "d_Images").string()}) {
    EXPECT_TRUE(hasLine(r.out, "written: " + f + "/?")) << f << "\n" << r.out;
    EXPECT_TRUE(fs::exists(f)) << f;
  }
  EXPECT_TRUE(contains(r.out, "written: " + tum + "/ (TUM folder: ")) << r.out;
  EXPECT_TRUE(fs::exists(tum + "/rgb.txt"));
}
