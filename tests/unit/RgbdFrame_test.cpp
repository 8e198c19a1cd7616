#include "rgbd_core/RgbdFrame.h"

#include <mrpt/maps/CColouredPointsMap.h>
#include <mrpt/obs/T3DPointsProjectionParams.h>

#include "TestData.h"
#include "rgbd_core/Intrinsics.h"

TEST(RgbdFrame, DepthKeepsFullPrecisionAndUnprojectsInMetres) {
  const auto cam = hrgbd::intrinsicsPreset("fr3");
  cv::Mat depth(480, 640, CV_16UC1, cv::Scalar(0)), bgr(480, 640, CV_8UC3, cv::Scalar(10, 20, 30));
  depth.at<uint16_t>(100, 200) = 12345;  // 2.469 m: not a whole metre, not a whole millimetre
  depth.at<uint16_t>(300, 400) = 5001;
  const auto obs = hrgbd::makeRgbdObservation(bgr, depth, 1.0 / 5000, cam, 1234.5);
  const auto d = hrgbd::depthMetres(*obs);
  EXPECT_NEAR(d.at<float>(100, 200), 2.469f, 1e-6);
  EXPECT_NEAR(d.at<float>(300, 400), 1.0002f, 1e-6);
  EXPECT_EQ(d.at<float>(0, 0), 0.0f);
  EXPECT_NEAR(hrgbd::timestampSeconds(*obs), 1234.5, 1e-6);

  // MRPT's own unprojection (x forward) sees the same depth.
  mrpt::maps::CColouredPointsMap pts;
  obs->unprojectInto(pts);
  ASSERT_EQ(pts.size(), 2u);
  std::vector<float> xs{pts.getPointsBufferRef_x()[0], pts.getPointsBufferRef_x()[1]};
  std::sort(xs.begin(), xs.end());
  EXPECT_NEAR(xs[0], 1.0002f, 1e-5);
  EXPECT_NEAR(xs[1], 2.469f, 1e-5);
}

TEST(RgbdFrame, RejectsMismatchedInputs) {
  const auto cam = hrgbd::intrinsicsPreset("ros_default");
  cv::Mat depth(480, 640, CV_16UC1, cv::Scalar(0));
  EXPECT_THROW(hrgbd::makeRgbdObservation(cv::Mat(240, 320, CV_8UC3), depth, 1e-3, cam, 0),
               std::invalid_argument);
  EXPECT_THROW(hrgbd::makeRgbdObservation({}, cv::Mat(480, 640, CV_32FC1), 1e-3, cam, 0),
               std::invalid_argument);
  EXPECT_THROW(hrgbd::makeRgbdObservation({}, depth, 0.0, cam, 0), std::invalid_argument);
}

TEST(Intrinsics, PresetsAndGuessing) {
  EXPECT_DOUBLE_EQ(hrgbd::intrinsicsPreset("fr1").fx(), 517.3);
  EXPECT_DOUBLE_EQ(hrgbd::intrinsicsPreset("fr3").cy(), 247.6);
  EXPECT_THROW(hrgbd::intrinsicsPreset("fr4"), std::invalid_argument);
  EXPECT_EQ(hrgbd::guessTumPreset("/d/rgbd_dataset_freiburg2_desk"), "fr2");
  EXPECT_EQ(hrgbd::guessTumPreset("/data/tum_fr3_teddy_200frames"), "fr3");
  EXPECT_EQ(hrgbd::guessTumPreset("/data/frames"), "");
  EXPECT_EQ(hrgbd::guessTumPreset("/data/fr1/rpy"), "fr1");  // a parent names it
  EXPECT_EQ(hrgbd::guessTumPreset("/runs_fr1/rgbd_dataset_freiburg3_teddy"), "fr3");
  EXPECT_EQ(hrgbd::guessTumPreset("/runs_fr1/rgbd_dataset_freiburg3_teddy/"), "fr3");
  EXPECT_EQ(hrgbd::guessTumPreset("C:\\runs_fr1\\tum_fr2_pair"), "fr2");
  EXPECT_EQ(hrgbd::guessTumPreset("/home/jeffr1/desk9"), "");  // "fr" inside a word
  EXPECT_EQ(hrgbd::guessTumPreset("fr3"), "fr3");
}
