// Inputs and outputs that are not regular files, and runs that do not end normally, through the
// real binaries: devices and FIFOs given as inputs (refused naming the file, or read once),
// outputs that are streams (each written once, messages kept out of them), full devices, outputs
// that would replace a dataset, a benchmark with nothing to run, and Ctrl-C / SIGTERM.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "AppRun.h"

namespace {

namespace fs = std::filesystem;
using hrgbd::test::app;
using hrgbd::test::catchesSigint;
using hrgbd::test::dataLines;
using hrgbd::test::exitCode;
using hrgbd::test::expectFailure;
using hrgbd::test::expectRefused;
using hrgbd::test::makeLongTumFolder;
using hrgbd::test::makeTumFolder;
using hrgbd::test::runApp;
using hrgbd::test::slurp;
using hrgbd::test::spawn;
using hrgbd::test::waitFor;

const std::string kOdometry = "hybrid-rgbd-odometry";
const std::string kDesk = std::string(HRGBD_SOURCE_DIR) + "/rawlogs/desk_near.rawlog";

/** Files in `dir` (recursively) whose name ends in ".tmp". */
std::vector<std::string> temporaries(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().extension() == ".tmp") out.push_back(e.path().string());
  return out;
}

// ---- 1. inputs that are not regular files ---------------------------------------------------

TEST(AppSpecialFiles, DevicesAndFoldersGivenAsInputsAreRefusedNamingTheFile) {
  // /dev/zero was read until memory ran out: seconds, gigabytes, then "std::bad_alloc".
  if (!fs::exists("/dev/zero")) GTEST_SKIP() << "no /dev/zero on this system";
  const fs::path dir = hrgbd::test::tempDir("special_devices");
  const auto tum = makeTumFolder(dir / "seq");
  const auto t = " -q -n 2 -t " + (dir / "t.txt").string();
  const std::string zero = "'/dev/zero' is a character device, not a regular file";
  expectFailure(kOdometry, "--print-config -c /dev/zero", {"config file " + zero});
  expectFailure(kOdometry, "-i /dev/zero" + t, {"rawlog " + zero});
  expectFailure("rgbd-eval", "/dev/zero " + tum + "/groundtruth.txt", {"trajectory file " + zero});
  expectFailure("tum2rawlog", tum + " " + (dir / "x.rawlog").string() + " -c /dev/zero",
                {"config file " + zero});
  expectFailure("rgbd-simulate",
                "-q --scene wall -n 2 --motion /dev/zero -o " + (dir / "m.rawlog").string(),
                {zero});
  std::ofstream(dir / "voc.ini") << "[Slam]\nenabled = true\nvocabulary = /dev/zero\n";
  expectFailure(kOdometry, "-i " + tum + t + " -c " + (dir / "voc.ini").string(),
                {"vocabulary " + zero});
  // An image that is a device or a folder, a list that is a device.
  const auto first = dataLines(slurp(dir / "seq" / "rgb.txt"))[0];
  const fs::path colour = dir / "seq" / first.substr(first.find(' ') + 1);
  fs::remove(colour);
  fs::create_symlink("/dev/zero", colour);
  expectFailure(kOdometry, "-i " + tum + t,
                {"colour image '" + colour.string() + "' is a character device"});
  fs::remove(colour);
  fs::create_directory(colour);
  expectFailure(kOdometry, "-i " + tum + t, {"colour image '" + colour.string() + "' is a folder"});
  fs::remove(dir / "seq" / "depth.txt");
  fs::create_symlink("/dev/zero", dir / "seq" / "depth.txt");
  expectFailure(kOdometry, "-i " + tum + t, {"depth.txt' is a character device"});
  EXPECT_FALSE(fs::exists(dir / "t.txt"));
}

TEST(AppSpecialFiles, AnIniFifoIsReadOnceAndARawlogFifoIsRefused) {
  const fs::path dir = hrgbd::test::tempDir("special_fifo_in");
  const auto ini = (dir / "c.ini").string();
  ASSERT_EQ(::mkfifo(ini.c_str(), 0600), 0);
  // One writer, once, as `-c <(...)` gives it: the INI file was opened twice and the second
  // open waited for ever (a pipe: "basic_string::_M_create").
  ASSERT_EQ(
      std::system(
          ("timeout 100 sh -c 'printf \"[ORB]\\nn_features = 321\\n\" > " + ini + "' &").c_str()),
      0);
  auto r = runApp(kOdometry, "--print-config -c " + ini);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("321"), std::string::npos) << r.out;
  // A rawlog is read twice (counted, then played): a FIFO is refused before it is opened.
  const auto rawlog = (dir / "r.rawlog").string();
  ASSERT_EQ(::mkfifo(rawlog.c_str(), 0600), 0);
  expectFailure(kOdometry, "-q -i " + rawlog + " -t " + (dir / "t.txt").string(),
                {"rawlog '" + rawlog + "' is a FIFO (named pipe), not a regular file"});
}

// ---- 2. an output that is a stream is written once --------------------------------------------

TEST(AppSpecialFiles, TheSlamModeWritesItsTrajectoryOnceToStdoutAndToAFifo) {
  // It wrote the odometry's poses as they came, then the optimised ones: 2N poses on stdout, and
  // a FIFO's second open waited for a reader that had gone.
  auto r = runApp(kOdometry, "-q --slam -n 6 -i " + kDesk + " -t /dev/stdout");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(dataLines(r.out).size(), 6u) << r.out;
  EXPECT_EQ(r.out.rfind("# hybrid-rgbd-odometry", 0), 0u) << "messages went into the output:\n"
                                                          << r.out;
  EXPECT_NE(r.err.find("trajectory (SLAM, optimised): /dev/stdout"), std::string::npos) << r.err;
  const fs::path dir = hrgbd::test::tempDir("special_fifo_out");
  const auto fifo = (dir / "t.fifo").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto cmd = "timeout 100 cat " + fifo + " > " + (dir / "got.txt").string() + " & " +
                   "timeout 100 " + app(kOdometry) + " -q --slam -n 6 -i " + kDesk + " -t " + fifo +
                   " > /dev/null 2>&1; code=$?; wait; exit $code";
  EXPECT_EQ(std::system(cmd.c_str()), 0);
  EXPECT_EQ(dataLines(slurp(dir / "got.txt")).size(), 6u);
}

TEST(AppSpecialFiles, ARawlogOnStdoutGetsNoMessagesAndNoGroundTruthBesideIt) {
  // tum2rawlog DIR /dev/stdout wrote its messages into the rawlog and the ground truth to
  // "/dev/stdout_groundtruth.txt".
  const fs::path dir = hrgbd::test::tempDir("special_stdout_rawlog");
  const auto tum = makeTumFolder(dir / "seq");
  const auto r = runApp("tum2rawlog", "-q " + tum + " /dev/stdout");
  const bool stray = fs::exists("/dev/stdout_groundtruth.txt");
  fs::remove("/dev/stdout_groundtruth.txt");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(stray);
  EXPECT_EQ(r.out.rfind("\x1f\x8b", 0), 0u) << "not a gzip stream: " << r.out.substr(0, 80);
  EXPECT_EQ(r.out.find("wrote"), std::string::npos);
  EXPECT_NE(r.err.find("ground-truth poses are not written"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("wrote 3 frames to /dev/stdout"), std::string::npos) << r.err;
}

// ---- 3. every output reports a full device ----------------------------------------------------

TEST(AppSpecialFiles, EveryOutputReportsAFullDevice) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
  const fs::path dir = hrgbd::test::tempDir("special_full");
  const auto t = (dir / "t.txt").string();
  // MRPT's saveToTextFile() checked no write: exit 0, the graph lost.
  expectFailure(kOdometry, "-q --slam -n 4 -i " + kDesk + " -t " + t + " --graph /dev/full",
                {"cannot write pose graph '/dev/full'"});
  expectFailure("rgbd-vocabulary",
                "-q --words 8 --every 2 -o /dev/full " + kDesk + " " +
                    std::string(HRGBD_SOURCE_DIR) + "/rawlogs/structure_near.rawlog",
                {"cannot write the vocabulary /dev/full"});
  expectFailure("rgbd-simulate", "-q --scene wall -n 2 --oni /dev/full", {"'/dev/full'"});
  EXPECT_FALSE(fs::exists("/dev/full_groundtruth.txt"));
}

// ---- 4. outputs never replace a dataset -------------------------------------------------------

TEST(AppSpecialFiles, SimulateRefusesAFolderHoldingADatasetItDidNotWrite) {
  const fs::path dir = hrgbd::test::tempDir("special_sim_tum");
  const auto tum = makeTumFolder(dir / "real");
  // A real dataset's lists: no "# file: rgbd-simulate" line.
  for (const auto* list : {"rgb.txt", "depth.txt"}) {
    const auto lines = dataLines(slurp(dir / "real" / list));
    std::ofstream out(dir / "real" / list);
    out << "# timestamp filename\n";
    for (const auto& l : lines) out << l << "\n";
  }
  const auto rgb = slurp(dir / "real" / "rgb.txt"), gt = slurp(dir / "real" / "groundtruth.txt");
  auto r = expectRefused("rgbd-simulate", "-q --scene wall -n 2 --tum " + tum);
  EXPECT_NE(r.err.find("holds a TUM dataset rgbd-simulate did not write"), std::string::npos)
      << r.err;
  EXPECT_EQ(slurp(dir / "real" / "rgb.txt"), rgb);
  EXPECT_EQ(slurp(dir / "real" / "groundtruth.txt"), gt);
  // Its ground truth alone is refused too.
  fs::create_directories(dir / "gt_only");
  fs::copy(dir / "real" / "groundtruth.txt", dir / "gt_only" / "groundtruth.txt");
  expectRefused("rgbd-simulate", "-q --scene wall -n 2 --tum " + (dir / "gt_only").string());
  // A folder the simulator wrote may be written again.
  makeTumFolder(dir / "sim");
  makeTumFolder(dir / "sim", 2);
  EXPECT_EQ(dataLines(slurp(dir / "sim" / "rgb.txt")).size(), 2u);
}

TEST(AppSpecialFiles, OutputsInsideATumImageFolderAreRefused) {
  const fs::path dir = hrgbd::test::tempDir("special_rgb_folder");
  const auto tum = makeTumFolder(dir / "seq");
  auto r = expectRefused(kOdometry, "-q -i " + tum + " -t " + tum + "/rgb/t.txt");
  EXPECT_NE(r.err.find("lies inside the TUM folder's image folder 'rgb'"), std::string::npos)
      << r.err;
  expectRefused("tum2rawlog", tum + " " + tum + "/depth/x.rawlog");
  EXPECT_FALSE(fs::exists(tum + "/rgb/t.txt"));
  EXPECT_FALSE(fs::exists(tum + "/depth/x.rawlog"));
}

// ---- 5. a benchmark that ran nothing fails ------------------------------------------------------

TEST(AppSpecialFiles, ABenchmarkWithNoSequenceToRunFails) {
  // It exited 0 with empty results.
  const fs::path dir = hrgbd::test::tempDir("special_bench_none");
  std::ofstream(dir / "b.ini") << "[Benchmark]\nmethods = rgb_only\nsim_scenes =\n"
                                  "real_sequences = missing_folder\noutput_folder = out\n"
                                  "cache_folder = cache\n";
  expectFailure("rgbd-benchmark", "-q -c " + (dir / "b.ini").string(),
                {"no benchmark result: every sequence was skipped", "missing_folder"});
  EXPECT_FALSE(fs::exists(dir / "out" / "results.md"));
  EXPECT_FALSE(fs::exists(dir / "out" / "results.csv"));
}

// ---- 6. Ctrl-C and SIGTERM ----------------------------------------------------------------------

TEST(AppSpecialFiles, CtrlCRemovesWhatIsIncompleteAndSaysWhatWasNotWritten) {
  // It left the hidden .tmp files and a half-written _Images/ folder.
  const fs::path dir = hrgbd::test::tempDir("special_sigint");
  const fs::path work = dir / "work";
  fs::create_directories(work);
  const auto pid =
      spawn({app("rgbd-simulate"), "-q", "--scene", "wall", "-n", "100000", "-o",
             (work / "s.rawlog").string(), "--images", "png", "--tum", (work / "tum").string()},
            dir);
  const bool started = waitFor(pid, [&] {
    std::error_code ec;
    const fs::directory_iterator it(work / "s_Images", ec);
    return !ec && std::distance(begin(it), end(it)) >= 3;
  });
  ASSERT_TRUE(started) << slurp(dir / "err");
  ASSERT_TRUE(catchesSigint(pid));
  kill(pid, SIGINT);
  EXPECT_EQ(exitCode(pid), 130) << slurp(dir / "err");
  const auto err = slurp(dir / "err");
  EXPECT_NE(err.find("rgbd-simulate: interrupted (SIGINT): stopped; not written: "),
            std::string::npos)
      << err;
  EXPECT_NE(err.find("rawlog '" + (work / "s.rawlog").string() + "'"), std::string::npos) << err;
  EXPECT_TRUE(temporaries(work).empty());
  EXPECT_FALSE(fs::exists(work / "s.rawlog"));
  EXPECT_FALSE(fs::exists(work / "s_Images"));
  EXPECT_FALSE(fs::exists(work / "tum"));
}

TEST(AppSpecialFiles, SigtermEndsAPlaybackWithoutPartialOutputs) {
  const fs::path dir = hrgbd::test::tempDir("special_sigterm");
  const fs::path work = dir / "work";
  fs::create_directories(work);
  const auto t = (work / "t.txt").string(), csv = (work / "f.csv").string();
  const auto tum = makeLongTumFolder(dir / "seq");
  const auto pid =
      spawn({app(kOdometry), "-q", "--no-slam", "-i", tum, "-t", t, "--csv", csv}, dir);
  const bool started = waitFor(pid, [&] { return temporaries(work).size() == 2; });
  ASSERT_TRUE(started) << slurp(dir / "err");
  ASSERT_TRUE(catchesSigint(pid));
  kill(pid, SIGTERM);
  EXPECT_EQ(exitCode(pid), 143) << slurp(dir / "err");
  const auto err = slurp(dir / "err");
  EXPECT_NE(err.find("hybrid-rgbd-odometry: terminated (SIGTERM): stopped; not written: "),
            std::string::npos)
      << err;
  EXPECT_NE(err.find("trajectory '" + t + "'"), std::string::npos) << err;
  EXPECT_NE(err.find("CSV '" + csv + "'"), std::string::npos) << err;
  EXPECT_TRUE(temporaries(work).empty());
  EXPECT_FALSE(fs::exists(t));
  EXPECT_FALSE(fs::exists(csv));
}

TEST(AppSpecialFiles, ASecondSignalEndsAProgramStuckWhereNoLoopLooks) {
  // Waiting for a writer on a FIFO: the first SIGINT is only noted, the second ends it.
  const fs::path dir = hrgbd::test::tempDir("special_second_signal");
  const auto ini = (dir / "c.ini").string();
  ASSERT_EQ(::mkfifo(ini.c_str(), 0600), 0);
  const auto pid = spawn({app(kOdometry), "--print-config", "-c", ini}, dir);
  ASSERT_TRUE(waitFor(pid, [&] { return catchesSigint(pid); }));
  kill(pid, SIGINT);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  kill(pid, SIGINT);
  EXPECT_EQ(exitCode(pid), 130);
  EXPECT_NE(slurp(dir / "err").find("interrupted again: stopped at once"), std::string::npos)
      << slurp(dir / "err");
}

}  // namespace
