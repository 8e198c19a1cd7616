// The seven apps' command lines, run as the user runs them: --help and --version print and exit 0
// without running the job; a refused command line exits 2 with "<app>: error:" and writes no
// output file; a runtime error exits 1. Each refusal has a control: the same command line with a
// valid value runs and writes its output, so "no file" means "nothing ran".
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
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
                                           "rgbd-live", "rgbd-simulate", "tum2rawlog",
                                           "rgbd-vocabulary"),
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

TEST(EvalCli, PlotsThatCannotBeWrittenAreRefusedBeforeTheWork) {
  const fs::path dir = hrgbd::test::tempDir("cli_eval_plot");
  const auto gt = kSource + "/rawlogs/desk_near_groundtruth.txt";
  const auto traj = (dir / "t.txt").string();
  for (const auto& bad : {(dir / "p.jpg").string(), (dir / "p").string(),
                          (dir / "missing" / "p.png").string(), dir.string()}) {
    auto r = expectRefused("rgbd-eval", gt + " " + gt + " --plot " + bad);
    EXPECT_NE(r.err.find("--plot"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("'" + bad), std::string::npos) << r.err;
    r = expectRefused("hybrid-rgbd-odometry", "-q -n 3 -m rgb_only -i " + kSource +
                                                  "/rawlogs/desk_near.rawlog -t " + traj +
                                                  " --plot " + bad);
    EXPECT_NE(r.err.find("'" + bad), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(traj)) << "nothing may run";
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 0);
  // Controls: the format follows the extension.
  const auto ok = runApp("rgbd-eval", gt + " " + gt + " --plot " + (dir / "p.svg").string());
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_EQ(hrgbd::test::slurp(dir / "p.svg").rfind("<?xml", 0), 0u);
  const auto run = runApp("hybrid-rgbd-odometry", "-q -n 3 -m rgb_only -i " + kSource +
                                                      "/rawlogs/desk_near.rawlog -t " + traj +
                                                      " --plot " + (dir / "p.pdf").string());
  EXPECT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(hrgbd::test::slurp(dir / "p.pdf").rfind("%PDF-", 0), 0u);
}

TEST(EvalCli, SeveralEstimatesGiveTheFiguresOfSingleRuns) {
  const fs::path dir = hrgbd::test::tempDir("cli_eval_multi");
  const auto gt = kSource + "/rawlogs/desk_near_groundtruth.txt";
  // Two estimates: the ground truth bent by a growing offset, every pose or every other one.
  std::ifstream in(gt);
  std::ofstream a(dir / "bent.txt"), b(dir / "sparse.txt");
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream f(line);
    std::string t;
    double v[7];
    f >> t >> v[0] >> v[1] >> v[2] >> v[3] >> v[4] >> v[5] >> v[6];
    std::ostringstream out;
    out << t << " " << v[0] + 0.002 * n << " " << v[1] << " " << v[2] - 0.001 * n;
    for (int k = 3; k < 7; ++k) out << " " << v[k];
    a << out.str() << "\n";
    if (n++ % 2 == 0) b << out.str() << "\n";
  }
  a.close(), b.close();
  const auto A = (dir / "bent.txt").string(), B = (dir / "sparse.txt").string();
  const auto single_a = runApp("rgbd-eval", gt + " " + A + " --json");
  const auto single_b = runApp("rgbd-eval", gt + " " + B + " --json");
  const auto png = (dir / "both.png").string();
  const auto both = runApp("rgbd-eval", gt + " " + A + " " + B + " --json --plot " + png);
  ASSERT_EQ(single_a.code, 0) << single_a.err;
  ASSERT_EQ(single_b.code, 0) << single_b.err;
  ASSERT_EQ(both.code, 0) << both.err;
  ASSERT_EQ(single_a.out.rfind("{\"ate_rmse\": ", 0), 0u) << "one estimate: one object";
  auto body = [](const std::string& json) { return json.substr(1, json.size() - 2); };  // no {, \n
  EXPECT_EQ(both.out, "[{\"estimate\": \"" + A + "\", " + body(single_a.out) +
                          ",\n {\"estimate\": \"" + B + "\", " + body(single_b.out) + "]\n");
  EXPECT_NE(single_a.out, single_b.out);
  EXPECT_EQ(hrgbd::test::slurp(png).rfind("\x89PNG\r\n\x1a\n", 0), 0u);
  const auto table = runApp("rgbd-eval", gt + " " + A + " " + B);
  EXPECT_EQ(table.code, 0) << table.err;
  EXPECT_EQ(std::count(table.out.begin(), table.out.end(), '\n'), 3) << table.out;
  EXPECT_NE(table.out.find(B), std::string::npos) << table.out;
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

TEST(VocabularyCli, RefusedCommandLinesAndTooLittleDataWriteNoVocabulary) {
  const fs::path dir = hrgbd::test::tempDir("cli_vocabulary");
  const auto out = (dir / "v.txt").string();
  const auto rawlog = kSource + "/rawlogs/desk_near.rawlog";
  for (const std::string bad : {"--words 1", "--words x", "--every 0", "--every -2", "", "-o ''"})
    expectRefused("rgbd-vocabulary", "-o " + out + " " + bad + (bad.empty() ? "" : " " + rawlog));
  expectRefused("rgbd-vocabulary", rawlog);  // no output
  const auto few = runApp("rgbd-vocabulary", "-q --words 100000 -o " + out + " " + rawlog);
  EXPECT_EQ(few.code, 1) << few.err;
  EXPECT_NE(few.err.find("too few descriptors for 100000 words"), std::string::npos) << few.err;
  const auto missing = runApp("rgbd-vocabulary", "-q -o " + out + " " + (dir / "nope").string());
  EXPECT_EQ(missing.code, 1) << missing.err;
  EXPECT_NE(missing.err.find("nope"), std::string::npos) << missing.err;
  EXPECT_FALSE(fs::exists(out));
  // 50 words from 10 frames of one desk: every word is in every frame, and the words cannot tell
  // the frames apart; refused
  const auto useless =
      runApp("rgbd-vocabulary", "-q --words 50 --every 2 -o " + out + " " + rawlog);
  EXPECT_EQ(useless.code, 1) << useless.err;
  EXPECT_NE(useless.err.find("every word is in every image"), std::string::npos) << useless.err;
  EXPECT_FALSE(fs::exists(out));
  // control: 400 words
  const auto ok = runApp("rgbd-vocabulary", "-q --words 400 --every 2 -o " + out + " " + rawlog);
  ASSERT_EQ(ok.code, 0) << ok.err;
  std::ifstream in(out);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "HRGBD_ORB_VOCABULARY 1 400");
  std::size_t words = 0;
  for (std::string l; std::getline(in, l);) words += l.size() > 64;
  EXPECT_EQ(words, 400u);
}
