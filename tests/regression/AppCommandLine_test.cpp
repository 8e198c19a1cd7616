// The six apps' command lines, run as the user runs them: --help and --version print and exit 0
// without running the job; a refused command line exits 2 with "<app>: error:" and writes no
// output file; a runtime error exits 1. Each refusal has a control: the same command line with a
// valid value runs and writes its output, so "no file" means "nothing ran".
#include <filesystem>
#include <string>

#include "AppRun.h"

namespace {

namespace fs = std::filesystem;
using hrgbd::test::expectRefused;
using hrgbd::test::runApp;

const std::string kSource = HRGBD_SOURCE_DIR;

class EveryApp : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryApp, HelpPrintsUsageAndExitsZero) {
  for (const std::string flag : {"--help", "-h"}) {
    const auto r = runApp(GetParam(), flag);
    EXPECT_EQ(r.code, 0) << flag << "\n" << r.err;
    EXPECT_NE(r.out.find("USAGE"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(GetParam() + " "), std::string::npos) << r.out;
    EXPECT_TRUE(r.err.empty()) << r.err;
  }
}

TEST_P(EveryApp, VersionPrintsNameAndVersionAndExitsZero) {
  const auto r = runApp(GetParam(), "--version");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind(GetParam() + " ", 0), 0u) << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;
}

TEST_P(EveryApp, UnknownOptionIsRefused) {
  const auto r = expectRefused(GetParam(), "--no-such-option");
  EXPECT_NE(r.err.find("--no-such-option"), std::string::npos) << r.err;
}

INSTANTIATE_TEST_SUITE_P(Apps, EveryApp,
                         ::testing::Values("hybrid-rgbd-odometry", "rgbd-benchmark", "rgbd-eval",
                                           "rgbd-live", "rgbd-simulate", "tum2rawlog"),
                         [](const auto& test) {
                           std::string n = test.param;
                           for (auto& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

TEST(HybridOdometryCli, RefusedCommandLinesWriteNoTrajectory) {
  const fs::path dir = hrgbd::test::tempDir("cli_odometry");
  const auto traj = (dir / "traj.txt").string();
  const auto base = "-q -i " + kSource + "/rawlogs/desk_near.rawlog -t " + traj + " ";
  for (const std::string bad : {"--methd rgb_only", "-n abc", "-n -1", "-n 1.5", "-n ''",
                                "--method nope", "-m HYBRID", "-i"}) {
    expectRefused("hybrid-rgbd-odometry", base + bad);
    EXPECT_FALSE(fs::exists(traj)) << bad;
  }
  const auto ok = runApp("hybrid-rgbd-odometry", base + "--method rgb_only -n 2");
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_TRUE(fs::exists(traj));
}

TEST(EvalCli, BadIntervalsAreRefusedAndNothingIsPlotted) {
  const fs::path dir = hrgbd::test::tempDir("cli_eval");
  const auto gt = kSource + "/rawlogs/desk_near_groundtruth.txt";
  const auto png = (dir / "eval.png").string();
  const auto base = gt + " " + gt + " --plot " + png + " ";
  for (const std::string bad :
       {"--rpe-delta nan", "--rpe-delta 0", "--rpe-delta -1", "--rpe-delta inf", "--rpe-delta ''",
        "--max-dt 0", "--max-dt abc", "--max-dt -0.02"}) {
    expectRefused("rgbd-eval", base + bad);
    EXPECT_FALSE(fs::exists(png)) << bad;
  }
  expectRefused("rgbd-eval", gt);  // the estimate is missing
  const auto ok = runApp("rgbd-eval", base + "--rpe-delta 0.5 --max-dt 0.01 --json");
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_NE(ok.out.find("\"rpe_delta\": 0.500"), std::string::npos) << ok.out;
  EXPECT_TRUE(fs::exists(png));
}

TEST(EvalCli, UnreadableInputIsARuntimeError) {
  const auto r = runApp("rgbd-eval", "/nonexistent/gt.txt /nonexistent/est.txt");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(r.err.rfind("rgbd-eval: error: ", 0), 0u) << r.err;
  EXPECT_EQ(r.err.find("--help"), std::string::npos) << "not a command-line error: " << r.err;
}

TEST(SimulateCli, RefusedCommandLinesWriteNoRawlog) {
  const fs::path dir = hrgbd::test::tempDir("cli_simulate");
  const auto rawlog = (dir / "sim.rawlog").string();
  for (const std::string bad : {"--scene nope", "--scene ''", "-n 0", "-n -1", "-n abc",
                                "--frames 2.5", "--seed x", "--images gif", "--far 1"}) {
    expectRefused("rgbd-simulate", "-o " + rawlog + " " + bad);
    EXPECT_FALSE(fs::exists(rawlog)) << bad;
  }
  expectRefused("rgbd-simulate", "--scene wall -n 2");  // no output given
  const auto ok = runApp("rgbd-simulate", "-o " + rawlog + " --scene wall -n 2 --images jpg");
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_TRUE(fs::exists(rawlog));
}

TEST(Tum2RawlogCli, RefusedCommandLinesWriteNoRawlog) {
  const fs::path dir = hrgbd::test::tempDir("cli_tum2rawlog");
  const auto rawlog = (dir / "seq.rawlog").string();
  const auto folder = kSource + "/rawlogs";  // any folder: the parse fails before it is read
  expectRefused("tum2rawlog", folder + " " + rawlog + " --images gif");
  expectRefused("tum2rawlog", folder);
  expectRefused("tum2rawlog", folder + " " + rawlog + " extra");
  EXPECT_FALSE(fs::exists(rawlog));
}

TEST(LiveCli, RefusedCommandLinesOpenNoSensorAndSaveNothing) {
  // Without the checks these would open the OpenNI2 sensor (exit 1 when there is none).
  const fs::path dir = hrgbd::test::tempDir("cli_live");
  const auto base = "--save-prefix " + (dir / "live_").string() + " ";
  for (const std::string bad : {"-n -1", "-n abc", "--rate -1", "--rate nan", "--hold nan",
                                "--hold inf", "--hold ''", "--hold -5"})
    expectRefused("rgbd-live", base + bad);
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(BenchmarkCli, MissingConfigIsARuntimeError) {
  const auto r = runApp("rgbd-benchmark", "-c /nonexistent/bench.ini");
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  EXPECT_EQ(r.err.rfind("rgbd-benchmark: error: ", 0), 0u) << r.err;
}

}  // namespace
