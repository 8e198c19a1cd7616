#include "rgbd_eval/Evaluate.h"

#include <mrpt/img/CImage.h>

#include <algorithm>
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

TEST(Evaluate, EndToStartErrorIsTheDriftFromFirstToLastPose) {
  // 0.11 m/s against 0.10 m/s over 10 s: the last pose is 0.1 m ahead, whatever the world frame.
  const CPose3D S(5, -3, 2, mrpt::DEG2RAD(30.0), 0, 0);
  auto est = line(0.11);
  for (auto& p : est) p.pose = S + p.pose;
  auto r = hrgbd::evaluateTrajectory(line(0.10), est);
  EXPECT_NEAR(r.end_to_start_trans, 0.1, 1e-9);
  EXPECT_NEAR(r.end_to_start_rot, 0, 1e-6);
  EXPECT_NE(hrgbd::toJson(r).find("\"end_to_start_trans\": 0.100000"), std::string::npos);
  EXPECT_NE(hrgbd::toText(r).find("end-to-start error    0.1000 m"), std::string::npos);
  // A last pose yawed by 2 deg more than the truth's, the earlier ones right: a rotation error
  // only, though the aligned ATE barely sees it.
  est = line(0.10);
  est.back().pose = est.back().pose + CPose3D(0, 0, 0, mrpt::DEG2RAD(2.0), 0, 0);
  r = hrgbd::evaluateTrajectory(line(0.10), est);
  EXPECT_NEAR(r.end_to_start_trans, 0, 1e-9);
  EXPECT_NEAR(r.end_to_start_rot, 2.0, 1e-6);
}

TEST(Evaluate, TooFewAssociatedPosesIsAnError) {
  auto est = line(0.1);
  for (auto& p : est) p.t += 0.05;  // beyond the 0.02 s association limit
  EXPECT_THROW(hrgbd::evaluateTrajectory(line(0.1), est), std::runtime_error);
  // An empty file says which one is empty ("only 0 poses lie within ..." did not).
  for (const bool empty_truth : {true, false}) {
    try {
      hrgbd::evaluateTrajectory(empty_truth ? hrgbd::Trajectory() : line(0.1),
                                empty_truth ? line(0.1) : hrgbd::Trajectory());
      FAIL() << "an empty trajectory was evaluated";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()),
                empty_truth ? "the ground truth has no pose" : "the estimate has no pose");
    }
  }
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

  // The plot is drawn: the estimate (Tableau blue) and the ground truth (dark grey) appear.
  const auto png = hrgbd::test::tempDir("evalplot") + "/p.png";
  hrgbd::plotEvaluation(orb, png, "fr2/desk ORB-SLAM2");
  mrpt::img::CImage img;
  ASSERT_TRUE(img.loadFromFile(png));
  const cv::Mat m = img.asCvMatRef();
  int blue = 0, grey = 0;
  for (int r = 0; r < m.rows; ++r)
    for (int c = 0; c < m.cols; ++c) {
      const auto px = m.at<cv::Vec3b>(r, c);  // BGR
      blue += std::abs(px[0] - 180) < 25 && std::abs(px[1] - 119) < 25 && px[2] < 70;
      grey += px[0] < 110 && px[0] > 40 && px[0] == px[1] && px[1] == px[2];
    }
  EXPECT_GT(blue, 2000);
  EXPECT_GT(grey, 300);
}

TEST(Evaluate, ParametersThatAreNotPositiveAreRefused) {
  // The command line refuses them too (AppCommandLine EvalCli test); here the library itself.
  for (double bad : {0.0, -1.0, std::nan(""), HUGE_VAL}) {
    hrgbd::EvalParams p;
    p.rpe_delta = bad;
    EXPECT_THROW(hrgbd::evaluateTrajectory(curve(), curve(), p), std::invalid_argument) << bad;
    p = {};
    p.max_time_difference = bad;
    EXPECT_THROW(hrgbd::evaluateTrajectory(curve(), curve(), p), std::invalid_argument) << bad;
  }
}

TEST(Evaluate, AnEstimateWithTwoPosesAtOneTimeIsAnError) {
  auto est = curve();
  est.insert(est.begin() + 50, est[50]);
  est[51].pose = CPose3D(5, 5, 5, 0, 0, 0);
  try {
    hrgbd::evaluateTrajectory(curve(), est);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("more than one pose at time stamp 105"), std::string::npos)
        << e.what();
  }
  // The ground truth may repeat a time stamp (TUM's own fr2/desk file does).
  auto gt = curve();
  gt.insert(gt.begin() + 50, gt[50]);
  EXPECT_NEAR(hrgbd::evaluateTrajectory(gt, curve()).ate_rmse, 0, 1e-9);
}

TEST(Evaluate, CoordinatesBeyondADoublesMetresAreAnErrorNotAWrongFigure) {
  auto far = curve();
  for (auto& p : far) p.pose.x_incr(1e150);  // 1e150 + 1 == 1e150: the shape is gone
  for (const auto& [gt, est] : {std::pair{curve(), far}, std::pair{far, far}}) {
    try {
      const auto r = hrgbd::evaluateTrajectory(gt, est);
      FAIL() << "expected an error, got ATE " << r.ate_rmse;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("1e+150 m"), std::string::npos) << e.what();
    }
  }
  // Large but representable offsets (UTM coordinates) give the same figures as without.
  auto offset = [](hrgbd::Trajectory t, double d) {
    for (auto& p : t) p.pose.x_incr(d), p.pose.y_incr(d);
    return t;
  };
  auto noisy = curve();
  for (std::size_t i = 0; i < noisy.size(); ++i) noisy[i].pose.z_incr(0.01 * std::sin(i));
  const auto ref = hrgbd::evaluateTrajectory(curve(), noisy);
  const auto utm = hrgbd::evaluateTrajectory(offset(curve(), 5e6), offset(noisy, 5e6));
  EXPECT_NEAR(utm.ate_rmse, ref.ate_rmse, 1e-7);
  EXPECT_NEAR(utm.ate_mean_unaligned, ref.ate_mean_unaligned, 1e-7);
  EXPECT_NEAR(utm.rpe_trans, ref.rpe_trans, 1e-7);
}

TEST(Evaluate, NoRpeIntervalIsSaidSoAndJsonStaysValid) {
  auto sparse = curve();
  for (std::size_t i = 0; i < sparse.size(); ++i) sparse[i].t = 100.0 + 3.0 * i;  // gaps > 2 s
  const auto r = hrgbd::evaluateTrajectory(sparse, sparse);
  EXPECT_EQ(r.rpe_pairs, 0u);
  const auto json = hrgbd::toJson(r);
  EXPECT_NE(json.find("\"rpe_trans\": null, \"rpe_rot\": null"), std::string::npos) << json;
  EXPECT_NE(hrgbd::toText(r).find("RPE                   none"), std::string::npos);
  // Whatever the figures, no inf or nan token reaches the JSON.
  auto bad = hrgbd::evaluateTrajectory(curve(), curve());
  bad.ate_rmse = HUGE_VAL;
  bad.rpe_rot = std::nan("");
  const auto text = hrgbd::toJson(bad);
  EXPECT_NE(text.find("\"ate_rmse\": null"), std::string::npos) << text;
  EXPECT_NE(text.find("\"rpe_rot\": null"), std::string::npos) << text;
  for (const auto* token : {"inf", "nan"}) EXPECT_EQ(text.find(token), std::string::npos) << text;
}

TEST(Evaluate, SeveralEstimatesAsJsonArrayAndTable) {
  const auto a = hrgbd::evaluateTrajectory(curve(), curve());
  const auto b = hrgbd::evaluateTrajectory(line(0.1), line(0.1, CPose3D(0, 0, 0, 0.3, 0, 0)));
  const auto json = hrgbd::toJsonArray({"a.txt", "dir/\"b\".txt"}, {a, b});
  EXPECT_EQ(json, "[{\"estimate\": \"a.txt\", " + hrgbd::toJson(a).substr(1) +
                      ",\n {\"estimate\": \"dir/\\\"b\\\".txt\", " + hrgbd::toJson(b).substr(1) +
                      "]\n");
  const auto table = hrgbd::toTable({"a.txt", "b.txt"}, {a, b});
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 3) << table;
  EXPECT_NE(table.find("a.txt"), std::string::npos);
  EXPECT_NE(table.find(" 101 "), std::string::npos) << table;
  EXPECT_NE(table.find("e2s [m]"), std::string::npos) << table;
  EXPECT_THROW(hrgbd::toTable({"a.txt"}, {a, b}), std::out_of_range);
}

TEST(Evaluate, RpeSeriesMatchesTheFigures) {
  const auto r = hrgbd::evaluateTrajectory(curve(), line(0.2));
  ASSERT_EQ(r.rpe_t.size(), r.rpe_pairs);
  ASSERT_EQ(r.rpe_trans_error.size(), r.rpe_pairs);
  ASSERT_EQ(r.rpe_rot_error.size(), r.rpe_pairs);
  double s = 0;
  for (double e : r.rpe_trans_error) s += e * e;
  EXPECT_NEAR(std::sqrt(s / r.rpe_pairs), r.rpe_trans, 1e-12);
  EXPECT_TRUE(std::is_sorted(r.rpe_t.begin(), r.rpe_t.end()));
  EXPECT_DOUBLE_EQ(r.rpe_t.front(), 100.0);
}
