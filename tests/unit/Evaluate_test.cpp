#include "rgbd_eval/Evaluate.h"

#include <mrpt/img/CImage.h>

#include <cmath>
#include <opencv2/core.hpp>

#include "TestData.h"
#include "rgbd_eval/EvalPlot.h"

using mrpt::poses::CPose3D;

namespace {
// 101 poses over 10 s along world x at `speed` m/s, each composed with `body` on the right.
hrgbd::Trajectory line(double speed, const CPose3D& body = CPose3D()) {
  hrgbd::Trajectory t;
  for (int i = 0; i <= 100; ++i)
    t.push_back({100.0 + 0.1 * i, CPose3D(speed * 0.1 * i, 0, 0, 0, 0, 0) + body});
  return t;
}
// A curved, rotating trajectory.
hrgbd::Trajectory curve() {
  hrgbd::Trajectory t;
  for (int i = 0; i <= 100; ++i) {
    const double s = 0.1 * i;
    t.push_back({100.0 + s, CPose3D(std::cos(s), std::sin(s), 0.1 * s, s, 0.2 * std::sin(s), 0.1)});
  }
  return t;
}
}  // namespace

TEST(Evaluate, IdenticalTrajectoriesHaveZeroError) {
  const auto r = hrgbd::evaluateTrajectory(curve(), curve());
  EXPECT_EQ(r.pairs, 101u);
  EXPECT_NEAR(r.ate_rmse, 0, 1e-9);
  EXPECT_NEAR(r.ate_mean_unaligned, 0, 1e-12);
  EXPECT_NEAR(r.rpe_trans, 0, 1e-12);
  EXPECT_NEAR(r.rpe_rot, 0, 1e-4);
}

TEST(Evaluate, WorldOffsetAndRotationCancelInBothAtes) {
  // Estimate expressed in another world frame: P_i = S Q_i.
  const CPose3D S(5, -3, 2, mrpt::DEG2RAD(30.0), mrpt::DEG2RAD(-10.0), mrpt::DEG2RAD(5.0));
  auto est = curve();
  for (auto& p : est) p.pose = S + p.pose;
  const auto r = hrgbd::evaluateTrajectory(curve(), est);
  EXPECT_NEAR(r.ate_rmse, 0, 1e-6);
  EXPECT_NEAR(r.ate_mean_unaligned, 0, 1e-9);
  EXPECT_NEAR(r.rpe_trans, 0, 1e-9);
}

TEST(Evaluate, ScaledLineHandComputed) {
  // Ground truth at 0.10 m/s, estimate at 0.11 m/s: errors grow as 0.01 t.
  const auto r = hrgbd::evaluateTrajectory(line(0.10), line(0.11));
  EXPECT_NEAR(r.ate_mean_unaligned, 0.01 * 5.0, 1e-9);  // mean of 0.01 t over t = 0..10
  // Aligned: centroids coincide, errors 0.01 |t - 5|; RMS of (t - 5) over 101 samples = sqrt(8.5).
  EXPECT_NEAR(r.ate_rmse, 0.01 * std::sqrt(8.5), 1e-6);
  EXPECT_NEAR(r.rpe_trans, 0.01, 1e-9);  // 0.01 m of error per 1 s interval
  EXPECT_NEAR(r.rpe_delta_used, 1.0, 1e-12);
  EXPECT_EQ(r.rpe_pairs, 91u);
}

TEST(Evaluate, KnownCameraRotationHandComputed) {
  // Same positions, camera yawed by 90 deg: Horn alignment sees no error, the paper's metric
  // (relative to the first pose) sees relative translation (x,0,0) as (0,-x,0): error sqrt(2) x.
  const auto r =
      hrgbd::evaluateTrajectory(line(0.1), line(0.1, CPose3D(0, 0, 0, mrpt::DEG2RAD(90.0), 0, 0)));
  EXPECT_NEAR(r.ate_rmse, 0, 1e-6);
  EXPECT_NEAR(r.ate_mean_unaligned, std::sqrt(2.0) * 0.5, 1e-9);  // mean x = 0.5 m
}

TEST(Evaluate, TooFewAssociatedPosesIsAnError) {
  auto est = line(0.1);
  for (auto& p : est) p.t += 0.05;  // beyond the 0.02 s association limit
  EXPECT_THROW(hrgbd::evaluateTrajectory(line(0.1), est), std::runtime_error);
}

TEST(Evaluate, PublishedEstimatesWithRealTimestampGaps) {
  HRGBD_REQUIRE_SHARED_DATA(data);
  const auto T = data + "/trajectories/";
  const auto orb =
      hrgbd::evaluateTrajectory(hrgbd::loadTumTrajectory(T + "fr2_desk_groundtruth_full.txt"),
                                hrgbd::loadTumTrajectory(T + "fr2_desk_estimate_orbslam2.txt"));
  const auto rgbdslam =
      hrgbd::evaluateTrajectory(hrgbd::loadTumTrajectory(T + "fr1_xyz_groundtruth_full.txt"),
                                hrgbd::loadTumTrajectory(T + "fr1_xyz_estimate_rgbdslam.txt"));
  // Bounds around the measured figures (0.0081 m and 0.0135 m ATE RMSE); both are accurate SLAM
  // systems on easy sequences, and neither can be better than the mocap noise (~1 mm).
  for (const auto* r : {&orb, &rgbdslam}) {
    EXPECT_GT(r->pairs, 700u);
    EXPECT_GT(r->ate_rmse, 0.002);
    EXPECT_LT(r->ate_rmse, 0.03);
    EXPECT_TRUE(std::isfinite(r->rpe_trans) && std::isfinite(r->rpe_rot));
    EXPECT_LT(r->rpe_trans, 0.05);
  }
  EXPECT_NEAR(orb.ate_rmse, 0.0081, 0.001);
  EXPECT_NEAR(rgbdslam.ate_rmse, 0.0135, 0.001);

  // The plot is drawn: red estimate and blue ground-truth pixels exist.
  const auto png = hrgbd::test::tempDir("evalplot") + "/p.png";
  hrgbd::plotEvaluation(orb, png, "fr2/desk ORB-SLAM2");
  mrpt::img::CImage img;
  ASSERT_TRUE(img.loadFromFile(png));
  const cv::Mat m = img.asCvMatRef();
  int red = 0, blue = 0;
  for (int r = 0; r < m.rows; ++r)
    for (int c = 0; c < m.cols; ++c) {
      const auto px = m.at<cv::Vec3b>(r, c);  // BGR
      red += px[2] > 180 && px[1] < 80 && px[0] < 80;
      blue += px[0] > 180 && px[2] < 80;
    }
  EXPECT_GT(red, 500);
  EXPECT_GT(blue, 500);
}
