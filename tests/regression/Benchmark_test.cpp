// rgbd-benchmark's reduced suite (the CI smoke test): every sequence x method runs, is evaluated
// and reaches the tables. No timing is asserted.
#include "rgbd_bench/Benchmark.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "TestData.h"
#include "rgbd_core/Config.h"

namespace {
std::string writeIni(const std::string& dir, const std::string& extra) {
  const auto ini = dir + "/bench.ini";
  std::ofstream(ini)
      << "[Benchmark]\nmethods = hybrid rgb_only depth_only opencv_rgbd hybrid_realtime\n"
         "sim_scenes = structure texture\nsim_far = false\nsim_frames = 6\n"
         "real_sequences = "
      << HRGBD_SOURCE_DIR << "/rawlogs/desk_near.rawlog " << dir << "/missing_folder\n"
      << extra;
  return ini;
}
}  // namespace

TEST(Benchmark, ReducedSuiteFillsEveryTable) {
  const auto dir = hrgbd::test::tempDir("benchmark");
  std::ostringstream log;
  // without the dense refinement, which registers the plain zig-zag from colour alone too
  const auto r = hrgbd::runBenchmark(writeIni(dir, "[Dense]\nenabled = false\n"), {}, log);
  // 2 simulated (rendered into the cache) + the bundled desk; the missing folder is listed.
  ASSERT_EQ(r.sequences.size(), 4u);
  EXPECT_EQ(r.sequences[3].skip_reason.rfind("not found", 0), 0u);
  ASSERT_EQ(r.runs.size(), 3u * 5u) << log.str();
  for (const auto& run : r.runs) {
    EXPECT_TRUE(run.error.empty()) << run.sequence << " " << run.method << ": " << run.error;
    ASSERT_TRUE(run.summary.evaluated) << run.sequence << " " << run.method;
    EXPECT_TRUE(std::isfinite(run.summary.eval.ate_mean_unaligned));
  }
  // The zig-zag needs the geometric path: hybrid registers it, RGB-only does not.
  const auto find = [&](const std::string& seq, const std::string& m) {
    for (const auto& run : r.runs)
      if (run.sequence == seq && run.method == m) return run.summary;
    return hrgbd::PlaybackSummary{};
  };
  EXPECT_EQ(find("sim/structure_near/sweep", "hybrid").registered, 6u);
  EXPECT_LT(find("sim/structure_near/sweep", "rgb_only").registered, 6u);
  // Played as a sensor: every frame of the bundled desk either tracked or counted as dropped.
  const auto live = find("real/desk_near", "hybrid_realtime");
  EXPECT_EQ(live.frames + live.dropped, 20u);
  EXPECT_TRUE(live.evaluated);

  std::ifstream md(dir + "/benchmark/results.md");
  std::stringstream text;
  text << md.rdbuf();
  for (const auto* heading :
       {"## Mean ATE, unaligned", "## ATE RMSE", "## RPE translation", "## Frames not registered",
        "## Time per frame, median", "## Targets", "| sim/texture_near/sweep |",
        "| real/desk_near |", "missing_folder: skipped", "## Real-time playback",
        "## Time per stage"})
    EXPECT_NE(text.str().find(heading), std::string::npos) << heading;
  std::ifstream csv(dir + "/benchmark/results.csv");
  std::string line;
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 1 + 15);

  // One figure per real sequence that ran (all five methods on it), linked from the report.
  ASSERT_EQ(r.figures.size(), 1u);
  EXPECT_EQ(r.figures[0].sequence, "real/desk_near");
  EXPECT_TRUE(r.figures[0].error.empty()) << r.figures[0].error;
  EXPECT_EQ(r.figures[0].file, "plots/real_desk_near.png");
  std::ifstream png(dir + "/benchmark/plots/real_desk_near.png", std::ios::binary);
  std::string header(8, '\0');
  png.read(header.data(), 8);
  EXPECT_EQ(header, "\x89PNG\r\n\x1a\n");
  EXPECT_NE(text.str().find("](plots/real_desk_near.png)"), std::string::npos);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir + "/benchmark/plots"),
                          std::filesystem::directory_iterator()),
            1);
}

TEST(Benchmark, RejectsUnknownKeysAndMethods) {
  const auto dir = hrgbd::test::tempDir("benchmark_bad");
  std::ostringstream log;
  EXPECT_THROW(hrgbd::runBenchmark(writeIni(dir, "sim_frame = 3\n"), {}, log), hrgbd::ConfigError);
  std::ofstream(dir + "/m.ini") << "[Benchmark]\nmethods = hybrid orb_slam\n";
  EXPECT_THROW(hrgbd::runBenchmark(dir + "/m.ini", {}, log), hrgbd::ConfigError);
}

TEST(Benchmark, ResultsThatCannotBeWrittenAreAnErrorNamingThem) {
  const auto dir = hrgbd::test::tempDir("benchmark_unwritable");
  std::ofstream(dir + "/bench.ini") << "[Benchmark]\nmethods = rgb_only\nsim_scenes =\n"
                                       "max_frames = 3\nreal_sequences = "
                                    << HRGBD_SOURCE_DIR << "/rawlogs/desk_near.rawlog\n";
  std::filesystem::create_directories(dir + "/benchmark/results.md");  // a folder of that name
  std::ostringstream log;
  try {
    hrgbd::runBenchmark(dir + "/bench.ini", {}, log);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write benchmark results '" + dir +
                                         "/benchmark/results.md': it is a folder"),
              std::string::npos)
        << e.what();
  }
}

TEST(Benchmark, CommandLineOverridesReplaceTheSectionsKeysAndLeaveTheFileAlone) {
  const auto dir = hrgbd::test::tempDir("benchmark_overrides");
  const std::string ini_text =
      std::string("[Benchmark]\nmethods = hybrid\nsim_scenes = structure\n") +
      "sim_far = false\nsim_frames = 3\nmax_frames = 3\nreal_sequences = " + HRGBD_SOURCE_DIR +
      "/rawlogs/desk_near.rawlog\n";
  std::ofstream(dir + "/bench.ini") << ini_text;
  std::ostringstream log;
  const auto r = hrgbd::runBenchmark(dir + "/bench.ini", {}, log, false,
                                     {{"methods", "rgb_only"}, {"sim_scenes", ""}});
  ASSERT_EQ(r.runs.size(), 1u) << log.str();
  EXPECT_EQ(r.runs[0].method, "rgb_only");
  EXPECT_EQ(r.runs[0].sequence, "real/desk_near");
  EXPECT_THROW(hrgbd::runBenchmark(dir + "/bench.ini", {}, log, false, {{"methods", "orb_slam"}}),
               hrgbd::ConfigError);
  std::ifstream in(dir + "/bench.ini");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), ini_text);  // MRPT's CConfigFile writes itself back when written to
}
