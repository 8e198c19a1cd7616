// A moving object in view (a person-sized box walking behind the simulated desk, as people do in
// TUM's fr2/desk_with_person): the tracker follows the static scene, not the object. Every frame
// registers, and the error is the same as without the object.
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "TestData.h"
#include "rgbd_app/Playback.h"
#include "rgbd_sim/Simulator.h"

namespace {

struct DeskRun {
  std::string folder;  // the TUM folder rendered
  double ate = 0;      // [m] aligned ATE of the default configuration (odometry only)
};

// 30 frames of the desk sweep with the walker at `walker_speed` [m/s], and the tracker's run
DeskRun desk(double walker_speed, const std::string& name) {
  const std::string dir = hrgbd::test::tempDir("moving_object_" + name);
  hrgbd::sim::SimParams p;
  p.scene = "desk";
  p.frames = 30;
  p.walker_speed = walker_speed;
  hrgbd::sim::SimOutputs out;
  out.tum_folder = dir + "/" + name;
  hrgbd::sim::simulate(p, out);

  hrgbd::PlaybackOptions o;
  o.config = std::string(HRGBD_SOURCE_DIR) + "/config.ini";
  o.input = out.tum_folder;
  o.trajectory = dir + "/" + name + ".txt";
  o.progress = false;
  o.ini_outputs = false;
  o.no_slam = true;
  std::ostringstream log;
  const auto s = hrgbd::runPlayback(o, log);
  EXPECT_TRUE(s.evaluated) << log.str();
  EXPECT_EQ(s.registered, s.frames) << name << ": " << log.str();
  return {out.tum_folder, s.eval.ate_rmse};
}

}  // namespace

TEST(MovingObject, TheTrackerFollowsTheStaticScene) {
  const DeskRun still = desk(0, "still"), walker = desk(0.6, "walker");
  // the walker is in view: the last depth images differ on thousands of pixels
  const std::string last = "/depth/1000.966667.png";
  const cv::Mat a = cv::imread(still.folder + last, cv::IMREAD_UNCHANGED);
  const cv::Mat b = cv::imread(walker.folder + last, cv::IMREAD_UNCHANGED);
  ASSERT_FALSE(a.empty() || b.empty()) << "no " << last;
  EXPECT_GT(cv::countNonZero(a != b), 5000);
  // measured: 2.0 mm with and without the walker, which crosses 0.6 m of the view behind the desk
  // (over 60 frames and other scenes, within 0.2 mm); a tracker that followed the object would be
  // off by decimetres
  EXPECT_LT(walker.ate, 0.004);
  EXPECT_LT(std::abs(walker.ate - still.ate), 0.001)
      << "without " << still.ate << " m, with " << walker.ate << " m";
}
