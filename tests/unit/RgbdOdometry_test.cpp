// The orchestrator on the bundled simulated sequence: flagged bad frames, recovery, no NaN.
#include "rgbd_odometry/RgbdOdometry.h"

#include <cmath>

#include "TestData.h"
#include "rgbd_io/RawlogSource.h"

using hrgbd::FrameResult;

namespace {
std::vector<mrpt::obs::CObservation3DRangeScan::Ptr> bundledFrames() {
  hrgbd::RawlogSource src(std::string(HRGBD_SOURCE_DIR) + "/rawlogs/desk_near.rawlog");
  std::vector<mrpt::obs::CObservation3DRangeScan::Ptr> v;
  while (auto o = src.next()) v.push_back(o);
  return v;
}
}  // namespace

TEST(RgbdOdometry, BadFramesAreFlaggedAndTrackingRecovers) {
  const auto frames = bundledFrames();
  ASSERT_GE(frames.size(), 10u);
  hrgbd::RgbdOdometry odo{hrgbd::OdometryParams()};
  EXPECT_EQ(odo.processObservation(*frames[0]).status, FrameResult::Status::FirstFrame);
  EXPECT_EQ(odo.processObservation(*frames[1]).status, FrameResult::Status::Ok);

  auto no_colour = *frames[2];
  no_colour.hasIntensityImage = false;
  const auto bad = odo.processObservation(no_colour);
  EXPECT_EQ(bad.status, FrameResult::Status::BadInput);
  EXPECT_NE(bad.detail.find("colour"), std::string::npos) << bad.detail;

  auto no_depth = *frames[3];
  no_depth.rangeImage.setZero();  // all-zero depth: every keypoint dropped
  const auto empty = odo.processObservation(no_depth);
  EXPECT_FALSE(empty.registered());

  auto bad_intrinsics = *frames[4];
  bad_intrinsics.cameraParamsIntensity.intrinsicParams(0, 0) = std::nan("");
  EXPECT_EQ(odo.processObservation(bad_intrinsics).status, FrameResult::Status::BadInput);

  // Frame 5 registers against frame 1, the last good one; poses stay finite throughout.
  const auto back = odo.processObservation(*frames[5]);
  EXPECT_EQ(back.status, FrameResult::Status::Ok) << back.detail;
  for (const auto& r : {bad, empty, back}) {
    for (double v : r.pose.asVectorVal()) EXPECT_TRUE(std::isfinite(v));
  }
}

TEST(RgbdOdometry, HoldPolicyKeepsThePoseOfTheLastFrame) {
  const auto frames = bundledFrames();
  hrgbd::OdometryParams p;
  p.on_failure = "hold";
  hrgbd::RgbdOdometry odo(p);
  odo.processObservation(*frames[0]);
  const auto good = odo.processObservation(*frames[1]);
  auto no_colour = *frames[2];
  no_colour.hasIntensityImage = false;
  const auto held = odo.processObservation(no_colour);
  EXPECT_EQ(held.pose, good.pose);
}

TEST(RgbdOdometry, DepthOnlyIsRefusedUntilTheGeometricPathExists) {
  hrgbd::OdometryParams p;
  p.method = "depth_only";
  EXPECT_THROW(hrgbd::RgbdOdometry{p}, std::runtime_error);
}
