// The orchestrator on the bundled simulated sequence: flagged bad frames, recovery, no NaN.
#include "rgbd_odometry/RgbdOdometry.h"

#include <cmath>

#include "TestData.h"
#include "rgbd_io/RawlogSource.h"

using hrgbd::FrameResult;

namespace {
// The paper's pipeline: frame to frame, sparse only (the paths' policies are tested on it).
hrgbd::OdometryParams paperParams() {
  hrgbd::OdometryParams p;
  p.keyframe_max_translation = 0;
  p.dense.enabled = false;
  return p;
}

std::vector<mrpt::obs::CObservation3DRangeScan::Ptr> bundledFrames(
    const std::string& name = "desk_near") {
  hrgbd::RawlogSource src(std::string(HRGBD_SOURCE_DIR) + "/rawlogs/" + name + ".rawlog");
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
  p.on_failure = hrgbd::FailurePolicy::Hold;
  hrgbd::RgbdOdometry odo(p);
  odo.processObservation(*frames[0]);
  const auto good = odo.processObservation(*frames[1]);
  auto no_colour = *frames[2];
  no_colour.hasIntensityImage = false;
  const auto held = odo.processObservation(no_colour);
  EXPECT_EQ(held.pose, good.pose);
}

TEST(RgbdOdometry, DepthOnlyAlwaysTakesTheGeometricPath) {
  const auto frames = bundledFrames();
  hrgbd::OdometryParams p = paperParams();
  p.method = hrgbd::Method::DepthOnly;
  hrgbd::RgbdOdometry odo(p);
  const auto first = odo.processObservation(*frames[0]);
  EXPECT_EQ(hrgbd::toString(first.path), "geometric");
  EXPECT_EQ(first.orb_features, 0u);  // ORB is not even run
  EXPECT_GT(first.features, 100u);
  const auto second = odo.processObservation(*frames[1]);
  EXPECT_EQ(hrgbd::toString(second.path), "geometric");
  EXPECT_EQ(second.status, FrameResult::Status::Ok) << second.detail;
}

TEST(RgbdOdometry, HybridSwitchesPathsOnTheOrbFeatureCount) {
  hrgbd::OdometryParams p = paperParams();  // min_orb_features = 50
  for (const auto& [sequence, path] :
       {std::pair{"desk_near", "photometric"}, std::pair{"structure_near", "geometric"}}) {
    const auto frames = bundledFrames(sequence);
    hrgbd::RgbdOdometry odo(p);
    for (std::size_t i = 0; i < 4; ++i) {
      const auto r = odo.processObservation(*frames[i]);
      EXPECT_EQ(hrgbd::toString(r.path), path)
          << sequence << " frame " << i << ": " << r.orb_features << " ORB";
      EXPECT_TRUE(r.registered()) << sequence << " frame " << i << ": " << r.detail;
      EXPECT_EQ(r.orb_features < 50u, std::string(path) == "geometric");
    }
  }
}

TEST(RgbdOdometry, GeometricFallbackRescuesPhotometricFailures) {
  const auto frames = bundledFrames("structure_near");
  hrgbd::OdometryParams p = paperParams();
  p.min_orb_features = 0;  // never switch on the count: the plain panels' few ORB matches fail
  for (const bool fallback : {false, true}) {
    p.geometric_fallback = fallback;
    hrgbd::RgbdOdometry odo(p);
    odo.processObservation(*frames[0]);
    const auto r = odo.processObservation(*frames[1]);
    EXPECT_EQ(r.registered(), fallback) << r.detail;
    EXPECT_EQ(hrgbd::toString(r.path), fallback ? "geometric" : "photometric");
  }
}

TEST(RgbdOdometry, FewPhotometricInliersHandOverToTheGeometricPath) {
  // The simulated desk registers photometrically on hundreds of inliers. A threshold above that
  // makes every frame try the geometric path, which registers the desk too and takes over.
  const auto frames = bundledFrames("desk_near");
  for (const int threshold : {0, 100000}) {
    hrgbd::OdometryParams p = paperParams();
    p.min_photometric_inliers = threshold;
    hrgbd::RgbdOdometry odo(p);
    odo.processObservation(*frames[0]);
    for (std::size_t i = 1; i < 4; ++i) {
      const auto r = odo.processObservation(*frames[i]);
      EXPECT_TRUE(r.registered()) << "frame " << i << ": " << r.detail;
      EXPECT_EQ(hrgbd::toString(r.path), threshold == 0 ? "photometric" : "geometric")
          << "frame " << i;
      if (threshold == 0) {
        EXPECT_GT(r.inliers, 100u);
      }
    }
  }
}

TEST(RgbdOdometry, CorruptValuesAndMismatchedSizesAreFlaggedNotFitted) {
  const auto frames = bundledFrames();
  hrgbd::RgbdOdometry odo{hrgbd::OdometryParams()};
  odo.processObservation(*frames[0]);
  // MRPT 2.5 stores depth as uint16 x rangeUnits, so it cannot hold NaN; the analogue of an
  // infinite value is saturation (0xFFFF = 13 m here). A third of the image saturated or zero:
  // those pixels are out of range; the frame still registers on the rest.
  auto nan_depth = *frames[1];
  for (int v = 0; v < nan_depth.rangeImage.rows() / 3; ++v)
    for (int u = 0; u < nan_depth.rangeImage.cols(); ++u)
      nan_depth.rangeImage(v, u) = (u % 2) ? 0xFFFF : 0;  // saturated = far beyond range
  const auto r1 = odo.processObservation(nan_depth);
  EXPECT_EQ(r1.status, FrameResult::Status::Ok) << r1.detail;
  // Colour and depth of different sizes.
  auto small = *frames[2];
  small.intensityImage = mrpt::img::CImage(320, 240, mrpt::img::CH_RGB);
  const auto r2 = odo.processObservation(small);
  EXPECT_EQ(r2.status, FrameResult::Status::BadInput);
  EXPECT_FALSE(r2.detail.empty());
  // Zero focal length.
  auto zero = *frames[3];
  zero.cameraParamsIntensity.intrinsicParams(0, 0) = 0;
  const auto r3 = odo.processObservation(zero);
  EXPECT_EQ(r3.status, FrameResult::Status::BadInput) << r3.detail;
  // A fully occluded frame (black image, no depth) is flagged; the next good frame registers.
  auto occluded = *frames[4];
  occluded.rangeImage.setZero();
  occluded.intensityImage = mrpt::img::CImage(640, 480, mrpt::img::CH_RGB);
  occluded.intensityImage.asCvMatRef().setTo(0);
  const auto r4 = odo.processObservation(occluded);
  EXPECT_FALSE(r4.registered());
  const auto r5 = odo.processObservation(*frames[5]);
  EXPECT_EQ(r5.status, FrameResult::Status::Ok) << r5.detail;
  for (const auto& r : {r1, r2, r3, r4, r5})
    for (double v : r.pose.asVectorVal()) EXPECT_TRUE(std::isfinite(v));
}

TEST(RgbdOdometry, SuddenJumpRegistersWithinLimitsAndIsFlaggedBeyondThem) {
  // Frames 0-2, then a jump to frame 15 (0.4 s later, about 15 cm). Within the default limits it
  // registers close to the truth; with a 5 cm limit it is flagged and its pose predicted at
  // constant velocity, and tracking goes on from frame 2.
  const auto frames = bundledFrames();
  hrgbd::RawlogSource src(std::string(HRGBD_SOURCE_DIR) + "/rawlogs/desk_near.rawlog");
  while (src.next()) {
  }
  const auto gt = src.groundTruth();
  const auto truth = (-gt[0].pose) + gt[15].pose;
  ASSERT_GT(truth.translation().norm(), 0.1);
  {
    hrgbd::RgbdOdometry odo(paperParams());
    for (int i : {0, 1, 2}) odo.processObservation(*frames[i]);
    const auto jump = odo.processObservation(*frames[15]);
    ASSERT_EQ(jump.status, FrameResult::Status::Ok) << jump.detail;
    EXPECT_LT((jump.pose.translation() - truth.translation()).norm(), 0.02);
    EXPECT_EQ(odo.processObservation(*frames[16]).status, FrameResult::Status::Ok);
  }
  hrgbd::OdometryParams p = paperParams();
  p.max_step_translation = 0.05;
  hrgbd::RgbdOdometry odo(p);
  mrpt::poses::CPose3D g1, g2;
  for (int i : {0, 1, 2}) (i == 1 ? g1 : g2) = odo.processObservation(*frames[i]).pose;
  const auto jump = odo.processObservation(*frames[15]);
  EXPECT_EQ(jump.status, FrameResult::Status::ImplausibleMotion);
  EXPECT_LT((jump.pose - (g2 + (g2 - g1))).norm(), 1e-9);  // constant velocity
  EXPECT_EQ(odo.processObservation(*frames[3]).status, FrameResult::Status::Ok);
}
