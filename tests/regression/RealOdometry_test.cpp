// Whole pipeline on the real TUM frames in ../shared/data/real, every method, with ATE bounds set
// from measurement (release build, seed 1): the bound is the measured value plus ~30 % margin.
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "TestData.h"
#include "rgbd_app/Playback.h"
#include "rgbd_core/Intrinsics.h"
#include "rgbd_core/RgbdFrame.h"

namespace {

struct Bound {
  const char* sequence;
  const char* method;
  double ate_rmse, ate_unaligned;  // [m] measured
};

// Aligned ATE RMSE and unaligned mean ATE measured on this machine with config.ini's defaults
// (the product's methods with the dense refinement and keyframes; before them hybrid gave 0.0504
// on teddy, depth_only 0.3665); the test allows 30 % + 2 mm above them.
const Bound kBounds[] = {
    {"tum_fr1_desk_9frames", "hybrid", 0.0026, 0.0040},
    {"tum_fr1_desk_9frames", "rgb_only", 0.0026, 0.0040},
    {"tum_fr1_desk_9frames", "ransac", 0.0043, 0.0100},
    {"tum_fr1_desk_9frames", "ransac_icp", 0.0030, 0.0126},
    {"tum_fr3_teddy_200frames", "hybrid", 0.0090, 0.0125},
    {"tum_fr3_teddy_200frames", "rgb_only", 0.0090, 0.0125},
    {"tum_fr3_teddy_200frames", "ransac", 0.0464, 0.0947},
    {"tum_fr3_teddy_200frames", "ransac_icp", 0.4006, 0.8998},
    {"tum_fr1_desk_9frames", "depth_only", 0.0026, 0.0040},
    {"tum_fr3_teddy_200frames", "depth_only", 0.0101, 0.0127},
    {"tum_fr3_cabinet_58keyframes", "hybrid", 0.0913, 0.1169},
    {"tum_fr3_cabinet_58keyframes", "depth_only", 0.4029, 0.6764},
    // the fast rotation (SLAM mode; the odometry alone 0.0222) and the real plain structure
    {"tum_fr1_rpy_240frames", "hybrid", 0.0127, 0.0247},
    {"tum_fr3_structure_notexture_far_130frames", "hybrid", 0.0049, 0.0062},
    // The peers. opencv_rgbd on teddy: 0.0582 / 0.0796 when unknown depth reached OpenCV as 0.
    {"tum_fr1_desk_9frames", "opencv_rgbd", 0.0035, 0.0120},
    {"tum_fr1_desk_9frames", "opencv_icp", 0.0018, 0.0094},
    {"tum_fr1_desk_9frames", "opencv_rgbd_icp", 0.0025, 0.0079},
    {"tum_fr1_desk_9frames", "open3d_color", 0.0039, 0.0125},
    {"tum_fr1_desk_9frames", "open3d_hybrid", 0.0032, 0.0089},
    {"tum_fr3_teddy_200frames", "opencv_rgbd", 0.0214, 0.0245},
};

// The frame of a colour and a depth PNG (TUM's depth unit, 1/5000 m); null if either is missing.
mrpt::obs::CObservation3DRangeScan::Ptr readFrame(const std::string& rgb, const std::string& depth,
                                                  const mrpt::img::TCamera& cam, double t) {
  const auto bgr = cv::imread(rgb, cv::IMREAD_COLOR);
  const auto d = cv::imread(depth, cv::IMREAD_ANYDEPTH);
  if (bgr.empty() || d.empty()) return nullptr;
  return hrgbd::makeRgbdObservation(bgr, d, 1.0 / 5000, cam, t);
}

}  // namespace

TEST(RealOdometry, AteWithinMeasuredBoundsForEveryMethod) {
  HRGBD_REQUIRE_SHARED_DATA(data);
  const auto dir = hrgbd::test::tempDir("real_odometry");
  for (const auto& b : kBounds) {
    hrgbd::PlaybackOptions o;
    o.input = data + "/real/" + b.sequence;
    o.trajectory = dir + "/traj.txt";
    o.method = b.method;
    o.progress = false;
    std::ostringstream log;
    const auto s = hrgbd::runPlayback(o, log);
    ASSERT_TRUE(s.evaluated) << log.str();
    // the fr1 camera's rolling shutter is undone by the product's dense refinement, not fr3's
    const bool undone = log.str().find("rolling shutter: 30 ms") != std::string::npos;
    const bool product = std::string(b.method) == "hybrid" || std::string(b.method) == "rgb_only" ||
                         std::string(b.method) == "depth_only";
    EXPECT_EQ(undone, product && std::string(b.sequence).find("fr1") != std::string::npos)
        << b.sequence << " " << b.method;
    const double ate = s.eval.ate_rmse;
    const double unaligned = s.eval.ate_mean_unaligned;
    std::printf("%-26s %-10s registered %3zu/%3zu  ATE RMSE %.4f m  unaligned mean %.4f m\n",
                b.sequence, b.method, s.registered, s.frames, ate, unaligned);
    EXPECT_LE(ate, 1.3 * b.ate_rmse + 0.002) << b.sequence << " " << b.method;
    EXPECT_LE(unaligned, 1.3 * b.ate_unaligned + 0.002) << b.sequence << " " << b.method;
    for (const auto& r : s.results) {
      EXPECT_TRUE(std::isfinite(r.pose.x()) && std::isfinite(r.pose.yaw()));
    }
  }
}

TEST(RealOdometry, Fr2PairRegistersWithSaneInliers) {
  HRGBD_REQUIRE_SHARED_DATA(data);
  const auto dir = data + "/real/slambook_fr2_pair/";
  const auto cam = hrgbd::intrinsicsPreset("fr2");
  hrgbd::OdometryParams p;
  p.method = hrgbd::Method::RgbOnly;
  hrgbd::RgbdOdometry odo(p);
  hrgbd::FrameResult r;
  for (int i = 1; i <= 2; ++i) {
    const auto obs =
        readFrame(dir + std::to_string(i) + ".png", dir + std::to_string(i) + "_depth.png", cam, i);
    ASSERT_TRUE(obs);
    r = odo.processObservation(*obs);
  }
  ASSERT_EQ(r.status, hrgbd::FrameResult::Status::Ok) << r.detail;
  std::printf("fr2 pair: %zu features, %zu matches, %zu inliers, sigma %.4f m, step %.3f m\n",
              r.features, r.matches, r.inliers, r.scale, r.pose.norm());
  EXPECT_GE(r.inliers, 50u);
  EXPECT_GE(r.inliers, r.matches / 3);
  EXPECT_LT(r.pose.norm(), 0.5);  // a hand-held step between nearby frames
}

// Frames out of order (an independent tester's shuffled teddy): frames 10 and 60 of teddy, 0.74 m
// and 44 deg apart, given one after the other. The sparse fit fails, and the refinement from the
// prediction (no motion) stopped 0.69 m and 44 deg from the truth, where it paired enough pixels:
// accepted as a step of 0.08 m. Only 19 % of its points agree with the reference depth: flagged.
TEST(RealOdometry, TeddyFramesFarApartAreFlaggedNotRegistered) {
  HRGBD_REQUIRE_SHARED_DATA(data);
  const auto dir = data + "/real/tum_fr3_teddy_200frames/";
  const auto cam = hrgbd::intrinsicsPreset("fr3");
  for (const double min_agreement : {0.0, hrgbd::DenseParams().min_depth_agreement}) {
    hrgbd::OdometryParams p;
    p.dense.min_depth_agreement = min_agreement;
    hrgbd::RgbdOdometry odo(p);
    hrgbd::FrameResult r;
    const char* frames[][2] = {{"1341841873.605856", "1341841873.605870"},   // frame 10
                               {"1341841875.285981", "1341841875.285994"}};  // frame 60
    for (int i = 0; i < 2; ++i) {
      const auto obs = readFrame(dir + "rgb/" + frames[i][0] + ".png",
                                 dir + "depth/" + frames[i][1] + ".png", cam, i / 30.0);
      ASSERT_TRUE(obs) << frames[i][0];
      r = odo.processObservation(*obs);
    }
    if (min_agreement > 0) {
      EXPECT_NE(r.status, hrgbd::FrameResult::Status::Ok);
      EXPECT_NE(r.detail.find("agree with the reference depth"), std::string::npos) << r.detail;
    } else {
      EXPECT_EQ(r.status, hrgbd::FrameResult::Status::Ok) << r.detail;  // the check catches it
      EXPECT_LT(r.pose.norm(), 0.3);  // far short of the true 0.74 m
    }
  }
}
