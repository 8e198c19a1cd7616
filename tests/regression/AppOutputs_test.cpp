// Every app's outputs, run as the user runs them: no output may overwrite an input or another
// output (refused before anything is written, naming both); a write that fails is an error naming
// the file (/dev/full), and a run that fails half-way leaves no output that looks complete; frame
// time stamps reach the trajectory and CSV exactly, or are refused naming the file and line.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "AppRun.h"

namespace {

namespace fs = std::filesystem;
using hrgbd::test::dataLines;
using hrgbd::test::expectFailure;
using hrgbd::test::expectRefused;
using hrgbd::test::makeTumFolder;
using hrgbd::test::runApp;
using hrgbd::test::slurp;

const std::string kSource = HRGBD_SOURCE_DIR;

/** A copy of the bundled rawlog (with its images and ground truth) in `dir`; returns its path. */
std::string copyDesk(const fs::path& dir) {
  for (const auto* name : {"desk_near.rawlog", "desk_near_groundtruth.txt", "desk_near_Images"})
    fs::copy(kSource + "/rawlogs/" + name, dir / name, fs::copy_options::recursive);
  return (dir / "desk_near.rawlog").string();
}

/** Rewrites the TUM folder's rgb.txt and depth.txt with `stamps` for its (sorted) images. */
void restamp(const fs::path& tum, const std::vector<std::string>& stamps) {
  for (const auto* list : {"rgb.txt", "depth.txt"}) {
    const auto old = dataLines(slurp(tum / list));
    std::ofstream out(tum / list);
    for (std::size_t i = 0; i < old.size() && i < stamps.size(); ++i)
      out << stamps[i] << " " << old[i].substr(old[i].find(' ') + 1) << "\n";
  }
}

// ---- 1. outputs never overwrite an input -------------------------------------------------

TEST(AppOutputs, OdometryRefusesOutputsThatNameAnInputAndLeavesThemAlone) {
  const fs::path dir = hrgbd::test::tempDir("outputs_inputs");
  const auto rawlog = copyDesk(dir);
  const auto gt = (dir / "desk_near_groundtruth.txt").string();
  const auto rawlog_bytes = slurp(rawlog), gt_bytes = slurp(gt);
  std::ofstream(dir / "cfg.ini") << "[Odometry]\nmethod = rgb_only\n";
  const auto run = "-q -n 2 -c " + (dir / "cfg.ini").string() + " -i " + rawlog + " ";
  const auto t = (dir / "t.txt").string();
  struct Case {
    std::string args, option, input;
  };
  for (const auto& c : std::vector<Case>{
           {"-t " + rawlog, "--trajectory", "the input rawlog"},
           {"-t " + (dir / "sub" / ".." / "desk_near.rawlog").string(), "--trajectory",
            "the input rawlog"},
           {"-t " + gt, "--trajectory", "the input rawlog's ground truth"},
           {"-t " + t + " --csv " + rawlog, "--csv", "the input rawlog"},
           {"-t " + t + " --map-ply " + (dir / "cfg.ini").string(), "--map-ply",
            "the configuration file"},
           {"-t " + t + " --simplemap " + (dir / "desk_near_Images" / "x.png").string(),
            "--simplemap", "the input rawlog's image folder"},
           {"-t " + t + " --plot " + gt, "--plot", "the input rawlog's ground truth"},
           // Its PNGs would go to desk_near_Images/, the input's image folder.
           {"-t " + t + " --output-rawlog " + (dir / "desk_near.out").string(),
            "--output-rawlog's image folder", "the input rawlog's image folder"},
           {"-t " + t + " --csv " + t, "--csv", "--trajectory"},
           {"-t " + t + " --map-scene " + (dir / "." / "t.txt").string(), "--map-scene",
            "--trajectory"}}) {
    const auto r = expectRefused("hybrid-rgbd-odometry", run + c.args);
    EXPECT_NE(r.err.find(c.option + " '"), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.input), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(t)) << c.args;
  }
  EXPECT_EQ(slurp(rawlog), rawlog_bytes);
  EXPECT_EQ(slurp(gt), gt_bytes);
  EXPECT_EQ(fs::file_size(dir / "cfg.ini"), std::string("[Odometry]\nmethod = rgb_only\n").size());
  // Control: the same run with distinct outputs works.
  const auto ok =
      runApp("hybrid-rgbd-odometry", run + "-t " + t + " --csv " + (dir / "f.csv").string());
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_EQ(dataLines(slurp(t)).size(), 2u);
}

TEST(AppOutputs, AnIniOutputNamingTheTumGroundTruthIsAConfigError) {
  const fs::path dir = hrgbd::test::tempDir("outputs_ini");
  const auto tum = makeTumFolder(dir / "seq");
  const auto gt_bytes = slurp(dir / "seq" / "groundtruth.txt");
  // Paths in [Playback] are relative to the INI file's folder.
  std::ofstream(dir / "seq" / "job.ini") << "[Playback]\ninput = .\ntrajectory = groundtruth.txt\n";
  const auto r = expectFailure("hybrid-rgbd-odometry", "-q -c " + tum + "/job.ini",
                               {"[Playback] trajectory", "the TUM folder's groundtruth.txt"});
  EXPECT_EQ(slurp(dir / "seq" / "groundtruth.txt"), gt_bytes);
  EXPECT_TRUE(r.out.empty()) << r.out;
  const auto first = dataLines(slurp(dir / "seq" / "rgb.txt"))[0];
  const auto image = tum + "/" + first.substr(first.find(' ') + 1);
  for (const auto& bad :
       {"--csv " + tum + "/rgb.txt", "--map-ply " + tum + "/depth.txt", "--csv " + image})
    expectRefused("hybrid-rgbd-odometry",
                  "-q -i " + tum + " -t " + (dir / "t.txt").string() + " " + bad);
  EXPECT_FALSE(fs::exists(dir / "t.txt"));
}

TEST(AppOutputs, Tum2RawlogSimulateEvalAndLiveRefuseOutputsOverInputs) {
  const fs::path dir = hrgbd::test::tempDir("outputs_apps");
  const auto tum = makeTumFolder(dir / "seq");
  const auto rgb = tum + "/rgb.txt", gt = tum + "/groundtruth.txt";
  const auto rgb_bytes = slurp(rgb), gt_bytes = slurp(gt);
  for (const auto& out : {rgb, tum + "/depth.txt", gt, tum + "/./groundtruth.txt"}) {
    const auto r = expectRefused("tum2rawlog", tum + " " + out);
    EXPECT_NE(r.err.find("the TUM folder's"), std::string::npos) << r.err;
  }
  std::ofstream(dir / "cfg.ini") << "[TumSource]\n";
  expectRefused("tum2rawlog",
                tum + " " + (dir / "cfg.ini").string() + " -c " + (dir / "cfg.ini").string());
  // rgbd-simulate: the motion file is an input (here the TUM folder's ground truth).
  auto r = expectRefused("rgbd-simulate", "--scene wall -n 2 --motion " + gt + " --tum " + tum);
  EXPECT_NE(r.err.find("the motion file (--motion)"), std::string::npos) << r.err;
  // Replaying a rawlog's ground truth into a rawlog of the same name would overwrite it.
  fs::copy(gt, dir / "m_groundtruth.txt");
  r = expectRefused("rgbd-simulate", "--scene wall -n 2 --motion " +
                                         (dir / "m_groundtruth.txt").string() + " -o " +
                                         (dir / "m.rawlog").string());
  EXPECT_NE(r.err.find("--rawlog's ground truth"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "m.rawlog"));
  fs::copy(gt, dir / "m.txt");
  // rgbd-eval: the plot may not overwrite either trajectory.
  r = expectRefused("rgbd-eval",
                    gt + " " + (dir / "m.txt").string() + " --plot " + (dir / "m.txt").string());
  EXPECT_NE(r.err.find("--plot '"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the estimate"), std::string::npos) << r.err;
  expectRefused("rgbd-eval", gt + " " + (dir / "m.txt").string() + " --plot " + gt);
  // rgbd-live: [s] writes <prefix>map.ply...; refused before any window or sensor is opened.
  std::ofstream(dir / "live_map.ply") << "[Map]\n";
  r = expectRefused("rgbd-live", "-i " + tum + " -c " + (dir / "live_map.ply").string() +
                                     " --save-prefix " + (dir / "live_").string());
  EXPECT_NE(r.err.find("the configuration file"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(rgb), rgb_bytes);
  EXPECT_EQ(slurp(gt), gt_bytes);
  EXPECT_EQ(slurp(dir / "live_map.ply"), "[Map]\n");
}

TEST(AppOutputs, BenchmarkResultsMayNotOverwriteItsConfiguration) {
  const fs::path dir = hrgbd::test::tempDir("outputs_benchmark");
  const std::string ini =
      "[Benchmark]\nmethods = rgb_only\nsim_scenes = wall\nsim_frames = 3\n"
      "output_folder = .\n";
  std::ofstream(dir / "results.md") << ini;
  const auto r = expectFailure("rgbd-benchmark", "-c " + (dir / "results.md").string(),
                               {"[Benchmark] output_folder's results.md", "configuration file"});
  EXPECT_EQ(slurp(dir / "results.md"), ini);
  EXPECT_FALSE(fs::exists(dir / "benchmark_cache")) << "nothing may run: " << r.out;
}

// ---- 2. write failures are errors; a failed run leaves no complete-looking output --------

TEST(AppOutputs, WriteFailuresAreErrorsNamingTheFile) {
  const fs::path dir = hrgbd::test::tempDir("outputs_full");
  const auto run = "-q -n 3 -m rgb_only -i " + kSource + "/rawlogs/desk_near.rawlog ";
  const auto t = (dir / "t.txt").string();
  for (const std::string option :
       {"-t", "--csv", "--plot", "--map-ply", "--map-scene", "--simplemap"}) {
    const auto args = option == "-t" ? "-t /dev/full" : "-t " + t + " " + option + " /dev/full";
    expectFailure("hybrid-rgbd-odometry", run + args, {"cannot write", "'/dev/full'"});
  }
  // The rawlog with poses keeps its images beside it: a device cannot hold it.
  expectFailure("hybrid-rgbd-odometry", run + "-t " + t + " --output-rawlog /dev/full",
                {"'/dev/full'", "regular file"});
  EXPECT_FALSE(fs::exists("/dev/full_Images"));
  // A device that takes the data is no error.
  const auto ok = runApp("hybrid-rgbd-odometry", run + "-t /dev/null --csv /dev/null");
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_TRUE(fs::is_character_file("/dev/null"));

  expectFailure("tum2rawlog", makeTumFolder(dir / "seq") + " /dev/full",
                {"cannot write rawlog '/dev/full'"});
  expectFailure("rgbd-simulate", "--scene wall -n 2 -o /dev/full",
                {"cannot write rawlog '/dev/full'"});
  const auto gt = kSource + "/rawlogs/desk_near_groundtruth.txt";
  expectFailure("rgbd-eval", gt + " " + gt + " --plot /dev/full",
                {"cannot write plot '/dev/full'"});
}

TEST(AppOutputs, OutputsWrittenAfterTheRunAreTriedBeforeIt) {
  // The map, simplemap and graph are written at the end: a missing folder failed only after the
  // whole run, with the trajectory and CSV already in place.
  const fs::path dir = hrgbd::test::tempDir("outputs_tried");
  const auto run = "-q -n 3 -m rgb_only -i " + kSource + "/rawlogs/desk_near.rawlog -t " +
                   (dir / "t.txt").string() + " --csv " + (dir / "f.csv").string() + " ";
  const auto missing = (dir / "missing" / "out").string();
  for (const std::string option : {"--map-ply", "--map-scene", "--simplemap", "--graph"}) {
    const auto slam = option == "--graph" ? "--slam " : "";
    expectFailure("hybrid-rgbd-odometry", run + slam + option + " " + missing,
                  {"cannot write " + option, "'" + missing + "'", "does not exist"});
    EXPECT_FALSE(fs::exists(dir / "t.txt")) << option;
    EXPECT_FALSE(fs::exists(dir / "f.csv")) << option;
  }
  // A usage error is said before any output is tried.
  const auto r = runApp("hybrid-rgbd-odometry", run + "--no-slam --graph " + missing);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("needs the SLAM mode"), std::string::npos) << r.err;
  for (const auto& e : fs::directory_iterator(dir)) ADD_FAILURE() << "left behind: " << e.path();
}

TEST(AppOutputs, ARunThatFailsHalfWayLeavesNoOutputThatLooksComplete) {
  const fs::path dir = hrgbd::test::tempDir("outputs_halfway");
  const auto tum = makeTumFolder(dir / "seq");
  // The third frame's colour image is gone: the run fails after two frames.
  const auto third = dataLines(slurp(dir / "seq" / "rgb.txt"))[2];
  fs::remove(dir / "seq" / third.substr(third.find(' ') + 1));
  std::ofstream(dir / "t.txt") << "# an earlier run\n";
  const auto outputs = "-t " + (dir / "t.txt").string() + " --csv " + (dir / "f.csv").string() +
                       " --map-ply " + (dir / "m.ply").string() + " --output-rawlog " +
                       (dir / "o.rawlog").string();
  expectFailure("hybrid-rgbd-odometry", "-q -m rgb_only -i " + tum + " " + outputs,
                {"cannot read colour image"});
  EXPECT_EQ(slurp(dir / "t.txt"), "# an earlier run\n");  // not replaced by two lines
  for (const auto* name : {"f.csv", "m.ply", "o.rawlog"}) EXPECT_FALSE(fs::exists(dir / name));
  expectFailure("tum2rawlog", tum + " " + (dir / "seq.rawlog").string(),
                {"cannot read colour image"});
  EXPECT_FALSE(fs::exists(dir / "seq.rawlog"));
  // No temporary file is left behind either.
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_NE(e.path().filename().string()[0], '.') << e.path();
}

// ---- 3. frame time stamps: exact, or refused naming the file and line --------------------

TEST(AppOutputs, FrameTimeStampsReachTheTrajectoryAndCsvExactly) {
  const fs::path dir = hrgbd::test::tempDir("outputs_stamps");
  const auto tum = makeTumFolder(dir / "seq");
  // 7 decimals at today's UNIX time: finer than a double holds there (238 ns).
  restamp(dir / "seq", {"1700000000.1234567", "1700000000.1567891", "1700000000.2000003"});
  const std::vector<std::string> want{"1700000000.123456700", "1700000000.156789100",
                                      "1700000000.200000300"};
  const auto t = dir / "t.txt", csv = dir / "f.csv";
  auto r = runApp("hybrid-rgbd-odometry",
                  "-q -m rgb_only -i " + tum + " -t " + t.string() + " --csv " + csv.string());
  ASSERT_EQ(r.code, 0) << r.err;
  auto check = [&](const fs::path& file, char sep) {
    const auto lines = dataLines(slurp(file));
    ASSERT_EQ(lines.size(), want.size() + (sep == ',' ? 1 : 0)) << file;
    for (std::size_t i = 0; i < want.size(); ++i)
      EXPECT_EQ(lines[i + (sep == ',' ? 1 : 0)].rfind(want[i] + sep, 0), 0u)
          << file << ": " << lines[i + (sep == ',' ? 1 : 0)];
  };
  check(t, ' ');
  check(csv, ',');
  // Through a rawlog (MRPT's 100 ns clock holds them) and back out.
  r = runApp("tum2rawlog", tum + " " + (dir / "seq.rawlog").string());
  ASSERT_EQ(r.code, 0) << r.err;
  r = runApp("hybrid-rgbd-odometry", "-q -m rgb_only -i " + (dir / "seq.rawlog").string() + " -t " +
                                         t.string() + " --csv " + csv.string());
  ASSERT_EQ(r.code, 0) << r.err;
  check(t, ' ');
  check(csv, ',');
}

TEST(AppOutputs, TimeStampsMrptCannotHoldAreRefusedNamingTheFileAndLine) {
  const fs::path dir = hrgbd::test::tempDir("outputs_bad_stamps");
  const auto tum = makeTumFolder(dir / "seq");
  const auto t = dir / "t.txt";
  struct Case {
    std::string stamp, why;
  };
  for (const auto& c : std::vector<Case>{{"-1", "negative"},
                                         {"1e308", "not below 1e11 s"},
                                         {"1700000000123456789", "not below 1e11 s"},
                                         {"1700000000.12345678", "finer than 100 ns"}}) {
    restamp(dir / "seq", {"1700000000", "1700000000.1", "1700000000.2"});
    // The second entry (line 2 of the rewritten list) gets the bad stamp.
    const auto lines = dataLines(slurp(dir / "seq" / "rgb.txt"));
    std::ofstream(dir / "seq" / "rgb.txt") << lines[0] << "\n"
                                           << c.stamp << lines[1].substr(lines[1].find(' ')) << "\n"
                                           << lines[2] << "\n";
    expectFailure("hybrid-rgbd-odometry", "-q -m rgb_only -i " + tum + " -t " + t.string(),
                  {"rgb.txt' line 2", c.why});
    EXPECT_FALSE(fs::exists(t)) << c.stamp;
    expectFailure("tum2rawlog", tum + " " + (dir / "x.rawlog").string(), {"rgb.txt' line 2"});
    EXPECT_FALSE(fs::exists(dir / "x.rawlog"));
  }
}

// ---- 4. rgbd-eval: a correct result or a clear error, JSON always valid ----------------

TEST(AppOutputs, EvalNeverPrintsInfOrNan) {
  const fs::path dir = hrgbd::test::tempDir("outputs_eval");
  const auto gt = kSource + "/rawlogs/desk_near_groundtruth.txt";
  const auto poses = dataLines(slurp(gt));
  auto write = [&](const std::string& name, auto edit) {
    std::ofstream out(dir / name);
    for (std::size_t i = 0; i < poses.size(); ++i) out << edit(i, poses[i]) << "\n";
    return (dir / name).string();
  };
  // Every line twice: two poses at one time stamp.
  const auto dup = write("dup.txt", [](std::size_t, const std::string& l) { return l + "\n" + l; });
  auto r = expectFailure("rgbd-eval", gt + " " + dup + " --json", {"dup.txt' line 2", "already"});
  EXPECT_TRUE(r.out.empty()) << r.out;
  // Coordinates of 1e150 m: a double has no metres left there.
  const auto far = write("far.txt", [](std::size_t, const std::string& l) {
    return l.substr(0, l.find(' ')) + " 1e150 1e150 1e150 0 0 0 1";
  });
  r = expectFailure("rgbd-eval", gt + " " + far + " --json", {"1e+150", "1e9 m"});
  EXPECT_TRUE(r.out.empty()) << r.out;
  expectFailure("rgbd-eval", far + " " + far, {"1e9 m"});
  // Poses 3 s apart with a 1 s interval: no RPE interval without a gap. "none", JSON null.
  const auto sparse = write("sparse.txt", [](std::size_t i, const std::string& l) {
    return std::to_string(100 + 3 * i) + l.substr(l.find(' '));
  });
  r = runApp("rgbd-eval", sparse + " " + sparse + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"rpe_trans\": null, \"rpe_rot\": null"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"rpe_pairs\": 0"), std::string::npos) << r.out;
  r = runApp("rgbd-eval", sparse + " " + sparse);
  EXPECT_NE(r.out.find("RPE                   none"), std::string::npos) << r.out;
  for (const auto* token : {"inf", "nan"}) EXPECT_EQ(r.out.find(token), std::string::npos);
  // An offset of 1e6 m (UTM-like) on both changes nothing.
  const auto utm = [](const std::string& l) {
    std::istringstream s(l);
    double v[8];
    for (double& x : v) s >> x;
    std::ostringstream o;
    o.precision(17);
    o << v[0] << " " << v[1] + 1e6 << " " << v[2] + 1e6 << " " << v[3];
    for (int k = 4; k < 8; ++k) o << " " << v[k];
    return o.str();
  };
  const auto gt_utm =
      write("gt_utm.txt", [&](std::size_t, const std::string& l) { return utm(l); });
  r = runApp("rgbd-eval", gt_utm + " " + gt_utm + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"ate_rmse\": 0.000000, \"ate_mean_unaligned\": 0.000000"),
            std::string::npos)
      << r.out;
}

}  // namespace

// ---- 5. progress on stderr when it is not a terminal; -q silences it -----------------------

TEST(AppOutputs, ProgressIsShownWhenPipedAndQuietSilencesIt) {
  const fs::path dir = hrgbd::test::tempDir("outputs_progress");
  const auto rawlog = kSource + "/rawlogs/desk_near.rawlog";
  auto r = runApp("hybrid-rgbd-odometry",
                  "-n 3 -m rgb_only -i " + rawlog + " -t " + (dir / "t.txt").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("3 frames in "), std::string::npos) << r.err;  // the final line
  EXPECT_EQ(r.err.find('\r'), std::string::npos) << "whole lines in a file: " << r.err;
  r = runApp("hybrid-rgbd-odometry",
             "-q -n 3 -m rgb_only -i " + rawlog + " -t " + (dir / "t.txt").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;

  for (const std::string quiet : {"", "-q "}) {
    const auto tum = (dir / ("seq" + quiet.substr(0, 1))).string();
    r = runApp("rgbd-simulate", quiet + "--scene wall -n 3 --tum " + tum);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err.empty(), !quiet.empty()) << r.err;
    EXPECT_EQ(r.err.find("3 frames in ") != std::string::npos, quiet.empty()) << r.err;
    // without the calibration.txt rgbd-simulate wrote, the camera is guessed from the folder's
    // name, which names no Freiburg camera: the intrinsics warning stays, -q or not
    fs::remove(fs::path(tum) / "calibration.txt");
    r = runApp("tum2rawlog", quiet + tum + " " + tum + ".rawlog");
    ASSERT_EQ(r.code, 0) << r.err;
    const auto warning = r.err.find("warning: TUM folder");
    ASSERT_NE(warning, std::string::npos) << r.err;
    const auto rest = r.err.substr(0, warning) + r.err.substr(r.err.find('\n', warning) + 1);
    EXPECT_EQ(rest.empty(), !quiet.empty()) << r.err;
    EXPECT_EQ(r.err.find("3 frames in ") != std::string::npos, quiet.empty()) << r.err;
  }
}
