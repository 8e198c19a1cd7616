// OpenNI recordings through the apps as a user runs them: rgbd-simulate --oni writes one with its
// ground truth, hybrid-rgbd-odometry plays it and is scored against it; broken ones are errors.
#include <filesystem>
#include <fstream>

#include "AppRun.h"

namespace {

/** A 10-frame simulated desk recording (rendered once per process). */
const std::string& recording() {
  static const std::string path = [] {
    const auto dir = hrgbd::test::scratchDir("oni_apps");
    const auto oni = dir + "/desk.oni";
    const auto r = hrgbd::test::runApp("rgbd-simulate", "--scene desk -n 10 --oni " + oni);
    EXPECT_EQ(r.code, 0) << r.out << r.err;
    return oni;
  }();
  return path;
}

}  // namespace

TEST(OniApps, SimulateWritesARecordingWithItsGroundTruth) {
  const auto& oni = recording();
  ASSERT_TRUE(std::filesystem::exists(oni));
  const auto gt = std::filesystem::path(oni).replace_extension().string() + "_groundtruth.txt";
  std::ifstream f(gt);
  std::string line;
  int poses = 0;
  double first = -1;
  while (std::getline(f, line))
    if (!line.empty() && line[0] != '#') {
      if (poses++ == 0) first = std::stod(line);
    }
  EXPECT_EQ(poses, 10);
  EXPECT_EQ(first, 0.0);  // the recording's clock starts with its first frame
}

TEST(OniApps, OdometryPlaysTheRecordingAndScoresItAgainstItsGroundTruth) {
  const auto& oni = recording();
  const auto traj = std::filesystem::path(oni).parent_path().string() + "/traj.txt";
  const auto r = hrgbd::test::runApp("hybrid-rgbd-odometry", "-c " + std::string(HRGBD_SOURCE_DIR) +
                                                                 "/config.ini --input " + oni +
                                                                 " --trajectory " + traj + " -q");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("input: OpenNI recording " + oni), std::string::npos) << r.out;
  const auto at = r.out.find("ATE RMSE (aligned)");
  ASSERT_NE(at, std::string::npos) << r.out;
  // Measured 0.0013 m, as for the same 10 frames written as a rawlog.
  EXPECT_LT(std::stod(r.out.substr(at + 18)), 0.005) << r.out;
}

TEST(OniApps, ABrokenRecordingIsAnErrorNamingIt) {
  const auto dir = hrgbd::test::scratchDir("oni_apps_bad");
  std::ofstream(dir + "/notes.oni") << "not a recording\n";
  hrgbd::test::expectFailure("hybrid-rgbd-odometry",
                             "--input " + dir + "/notes.oni --trajectory " + dir + "/t.txt",
                             {"OpenNI recording " + dir + "/notes.oni", "not an ONI file"});
  hrgbd::test::expectFailure("hybrid-rgbd-odometry",
                             "--input " + dir + "/missing.oni --trajectory " + dir + "/t.txt",
                             {dir + "/missing.oni", "missing or unreadable"});
}
