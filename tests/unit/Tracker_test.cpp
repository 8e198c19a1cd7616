// The tracker's policies with a fake registration that returns scripted results: chaining
// (eq. 8), the reference kept across failures, constant-velocity and hold predictions, the
// plausibility limits, bad input and reset.
#include <gtest/gtest.h>

#include <deque>

#include "rgbd_core/Config.h"
#include "rgbd_core/Intrinsics.h"
#include "rgbd_core/RgbdFrame.h"
#include "rgbd_odometry/RgbdOdometry.h"

using hrgbd::FrameResult;
using Status = hrgbd::FrameResult::Status;

namespace {

// The fake's path: not the default, so that a path the tracker did not copy would show.
const hrgbd::FramePath kFakePath{hrgbd::FramePath::Sparse::Geometric,
                                 hrgbd::FramePath::Refined::Prediction};

// Returns the scripted results in order; records the time stamps of the frames it aligned.
class FakeRegistration : public hrgbd::Registration {
 public:
  struct Log {
    std::vector<std::pair<double, double>> aligned;  // (current t, reference t)
    std::vector<bool> guessed;                       // whether a motion prediction came along
    // the velocities of the current frame and of the reference (NaN: none)
    std::vector<std::pair<Eigen::Matrix<double, 6, 1>, Eigen::Matrix<double, 6, 1>>> velocities;
    int prepared = 0;
  };
  FakeRegistration(std::deque<hrgbd::RegistrationResult> script, Log& log)
      : m_script(std::move(script)), m_log(log) {}
  hrgbd::FrameFeatures prepare(hrgbd::Frame&) override {
    ++m_log.prepared;
    return {kFakePath, 7, 7, {}};
  }
  hrgbd::RegistrationResult align(hrgbd::Frame& cur, hrgbd::Frame& ref) override {
    m_log.aligned.emplace_back(cur.image.t, ref.image.t);
    m_log.guessed.push_back(cur.guess.has_value());
    const auto none = Eigen::Matrix<double, 6, 1>::Constant(std::nan(""));
    m_log.velocities.emplace_back(cur.velocity.value_or(none), ref.velocity.value_or(none));
    if (m_script.empty()) {
      ADD_FAILURE() << "the tracker registered more frames than scripted";
      return {};
    }
    auto r = m_script.front();
    m_script.pop_front();
    return r;
  }

 private:
  std::deque<hrgbd::RegistrationResult> m_script;
  Log& m_log;
};

hrgbd::RegistrationResult step(double x, double yaw_deg = 0, Status s = Status::Ok) {
  hrgbd::RegistrationResult r;
  r.status = s;
  r.T = Eigen::Translation3d(x, 0, 0) *
        Eigen::AngleAxisd(yaw_deg * M_PI / 180, Eigen::Vector3d::UnitY());
  r.detail = s == Status::Ok ? "" : "scripted failure";
  r.inliers = 100;
  return r;
}

// A small valid frame (64 x 48, flat wall at 1 m) at time t.
mrpt::obs::CObservation3DRangeScan::Ptr frame(double t) {
  const cv::Mat bgr(48, 64, CV_8UC3, cv::Scalar(90, 120, 150));
  const cv::Mat depth(48, 64, CV_16UC1, cv::Scalar(5000));
  return hrgbd::makeRgbdObservation(bgr, depth, 1.0 / 5000,
                                    hrgbd::pinholeCamera(50, 50, 31.5, 23.5, 64, 48), t);
}

struct Run {
  FakeRegistration::Log log;
  std::vector<FrameResult> results;
};

// The frames at `times` (default: 100, 101, ...), one more than the script.
Run track(const std::deque<hrgbd::RegistrationResult>& script, hrgbd::OdometryParams p = {},
          std::vector<double> times = {}) {
  for (std::size_t i = times.size(); i <= script.size(); ++i) times.push_back(100.0 + i);
  Run run;
  hrgbd::RgbdOdometry odo(p, std::make_unique<FakeRegistration>(script, run.log));
  for (std::size_t i = 0; i <= script.size(); ++i)
    run.results.push_back(odo.processObservation(*frame(times[i])));
  return run;
}

// Optical x of the pose (poses are optical frames in the first optical frame, TUM convention).
double x(const FrameResult& r) { return r.pose.x(); }

}  // namespace

TEST(Tracker, ChainsEachStepOntoTheReference) {
  const auto run = track({step(0.1), step(0.2, 10), step(0.05)});
  ASSERT_EQ(run.results.size(), 4u);
  EXPECT_EQ(run.results[0].status, Status::FirstFrame);
  EXPECT_EQ(run.results[0].pose, mrpt::poses::CPose3D());
  EXPECT_EQ(run.results[0].path, kFakePath);  // what the registration said
  EXPECT_EQ(run.results[0].features, 7u);
  // G_n = G_ref T (eq. 8), the reference being the previous frame while every step registers.
  const auto g1 = hrgbd::toPose(step(0.1).T);
  const auto g2 = g1 + hrgbd::toPose(step(0.2, 10).T);
  const auto g3 = g2 + hrgbd::toPose(step(0.05).T);
  EXPECT_NEAR((run.results[1].pose - g1).norm(), 0, 1e-12);
  EXPECT_NEAR((run.results[2].pose - g2).norm(), 0, 1e-12);
  EXPECT_NEAR((run.results[3].pose - g3).norm(), 0, 1e-12);
  EXPECT_EQ(run.log.prepared, 4);
  const std::vector<std::pair<double, double>> pairs{{101, 100}, {102, 101}, {103, 102}};
  EXPECT_EQ(run.log.aligned, pairs);
}

TEST(Tracker, FailedFramesArePredictedAtConstantVelocityAndKeepTheReference) {
  const auto run = track({step(0.1), step(0, 0, Status::TooFewInliers), step(0.25)});
  EXPECT_EQ(run.results[2].status, Status::TooFewInliers);
  EXPECT_EQ(run.results[2].detail, "scripted failure");
  EXPECT_NEAR(x(run.results[2]), 0.2, 1e-12);  // 0.1 + the last motion, 0.1
  // Frame 103 registers against 101, the last registered frame, not the failed 102.
  EXPECT_EQ(run.log.aligned.back(), std::make_pair(103.0, 101.0));
  EXPECT_NEAR(x(run.results[3]), 0.35, 1e-12);  // 0.1 + 0.25 from frame 101
}

TEST(Tracker, HoldPolicyKeepsThePose) {
  hrgbd::OdometryParams p;
  p.on_failure = hrgbd::FailurePolicy::Hold;
  const auto run = track({step(0.1), step(0, 0, Status::TooFewMatches)}, p);
  EXPECT_EQ(run.results[2].status, Status::TooFewMatches);
  EXPECT_EQ(run.results[2].pose, run.results[1].pose);
}

TEST(Tracker, ALongFlaggedRunIsExtrapolatedOverMaxPredictedFramesThenHeld) {
  std::deque<hrgbd::RegistrationResult> script{step(0.1), step(0.1)};
  for (int i = 0; i < 8; ++i) script.push_back(step(0, 0, Status::TooFewMatches));
  for (const int max_predicted : {5, 0}) {
    hrgbd::OdometryParams p;
    p.max_predicted_frames = max_predicted;
    const auto run = track(script, p);
    ASSERT_EQ(run.results.size(), 11u);
    // frames 3-7 extrapolated by 0.1 each; then held at 0.7, or on to 1.0 without the limit
    EXPECT_NEAR(x(run.results[7]), 0.7, 1e-9);
    EXPECT_NEAR(x(run.results[10]), max_predicted ? 0.7 : 1.0, 1e-9);
    EXPECT_EQ(run.results[10].status, Status::TooFewMatches);
  }
}

TEST(Tracker, ImplausibleStepsAreFlaggedNotChained) {
  hrgbd::OdometryParams p;
  p.max_step_translation = 0.3;
  p.max_step_rotation_deg = 20;
  const auto run = track({step(0.1), step(0.4), step(0.1, 25), step(0.29, 19)}, p);
  EXPECT_EQ(run.results[1].status, Status::Ok);
  EXPECT_EQ(run.results[2].status, Status::ImplausibleMotion);
  EXPECT_NE(run.results[2].detail.find("0.4"), std::string::npos) << run.results[2].detail;
  EXPECT_EQ(run.results[3].status, Status::ImplausibleMotion);  // 25 deg
  EXPECT_EQ(run.results[4].status, Status::Ok);                 // just inside both limits
  EXPECT_EQ(run.log.aligned.back(), std::make_pair(104.0, 101.0));
}

TEST(Tracker, BadInputIsFlaggedWithoutCallingTheRegistration) {
  FakeRegistration::Log log;
  hrgbd::RgbdOdometry odo(hrgbd::OdometryParams(),
                          std::make_unique<FakeRegistration>(
                              std::deque<hrgbd::RegistrationResult>{step(0.1), step(0.1)}, log));
  odo.processObservation(*frame(100));
  odo.processObservation(*frame(101));
  auto no_depth = frame(102);
  no_depth->hasRangeImage = false;
  const auto bad = odo.processObservation(*no_depth);
  EXPECT_EQ(bad.status, Status::BadInput);
  EXPECT_EQ(bad.path, hrgbd::FramePath{});  // none, no refinement
  EXPECT_FALSE(bad.detail.empty());
  EXPECT_EQ(log.prepared, 2);
  EXPECT_EQ(log.aligned.size(), 1u);
  EXPECT_NEAR(x(bad), 0.2, 1e-12);  // constant velocity
}

TEST(Tracker, ResetMakesTheNextFrameTheOrigin) {
  FakeRegistration::Log log;
  hrgbd::RgbdOdometry odo(
      hrgbd::OdometryParams(),
      std::make_unique<FakeRegistration>(std::deque<hrgbd::RegistrationResult>{step(0.1)}, log));
  odo.processObservation(*frame(100));
  odo.processObservation(*frame(101));
  ASSERT_NE(odo.pose(), mrpt::poses::CPose3D());
  odo.reset();
  const auto r = odo.processObservation(*frame(102));
  EXPECT_EQ(r.status, Status::FirstFrame);
  EXPECT_EQ(r.pose, mrpt::poses::CPose3D());
}

TEST(Tracker, BaselineMethodsNeedTheBaselinesLibrary) {
  hrgbd::OdometryParams p;
  p.method = hrgbd::Method::Ransac;
  EXPECT_THROW(hrgbd::RgbdOdometry{p}, hrgbd::ConfigError);
}

TEST(Tracker, KeyframesAreKeptUntilTheyWearOut) {
  hrgbd::OdometryParams p;
  p.keyframe_max_translation = 0.15;
  p.keyframe_max_rotation_deg = 5;
  p.keyframe_min_inliers = 50;
  auto few_inliers = step(0.02);
  few_inliers.inliers = 10;
  auto enough_inliers = step(0.01);
  enough_inliers.inliers = 60;
  // T is each frame's motion from the keyframe it was registered against.
  const auto run =
      track({step(0.1), step(0.2), step(0.05), step(0.06, 6), few_inliers, enough_inliers}, p);
  const std::vector<std::pair<double, double>> pairs{{101, 100}, {102, 100}, {103, 102},
                                                     {104, 102}, {105, 104}, {106, 105}};
  EXPECT_EQ(run.log.aligned, pairs);
  std::vector<bool> keyframes;
  for (const auto& r : run.results) keyframes.push_back(r.keyframe);
  // first frame; 0.1 m kept; 0.2 m > 0.15; kept; 6 deg > 5; 10 inliers < 50; 60 inliers kept
  EXPECT_EQ(keyframes, (std::vector<bool>{true, false, true, false, true, true, false}));
  EXPECT_NEAR(x(run.results[2]), 0.2, 1e-12);
  EXPECT_NEAR(x(run.results[3]), 0.25, 1e-12);  // 0.2 (keyframe 102) + 0.05
}

TEST(Tracker, FrameToFrameMakesEveryRegisteredFrameTheReference) {
  const auto run = track({step(0.3), step(0.3)});  // keyframe_max_translation = 0 by default
  EXPECT_TRUE(run.results[1].keyframe);
  EXPECT_TRUE(run.results[2].keyframe);
  EXPECT_EQ(run.log.aligned.back(), std::make_pair(102.0, 101.0));
}

TEST(Tracker, AfterFailuresInARowAFlaggedFrameBecomesTheKeyframe) {
  hrgbd::OdometryParams p;
  p.keyframe_max_translation = 1;  // no keyframe by motion here
  p.keyframe_after_failures = 3;
  const auto fail = step(0, 0, Status::TooFewInliers);
  // two failures, a registered frame (the count starts again), then three failures
  const auto run = track({step(0.1), fail, fail, step(0.3), fail, fail, fail, step(0.05)}, p);
  std::vector<bool> keyframes;
  for (const auto& r : run.results) keyframes.push_back(r.keyframe);
  EXPECT_EQ(keyframes,
            (std::vector<bool>{true, false, false, false, false, false, false, true, false}));
  // frame 107, the third failure in a row, is flagged at its constant-velocity prediction and
  // is the keyframe there: 0.3 (frame 104, registered against 100) + 3 x 0.1 (the motion last
  // measured between two registered frames, 100 -> 101)
  EXPECT_EQ(run.results[7].status, Status::TooFewInliers);
  EXPECT_FALSE(run.results[7].registered());
  EXPECT_NEAR(x(run.results[7]), 0.6, 1e-12);
  EXPECT_EQ(run.log.aligned.back(), std::make_pair(108.0, 107.0));
  EXPECT_NEAR(x(run.results[8]), 0.65, 1e-12);

  p.keyframe_after_failures = 0;  // never: frame 108 still registers against frame 100
  const auto kept = track({step(0.1), fail, fail, step(0.3), fail, fail, fail, step(0.05)}, p);
  EXPECT_FALSE(kept.results[7].keyframe);
  EXPECT_EQ(kept.log.aligned.back(), std::make_pair(108.0, 100.0));
  EXPECT_NEAR(x(kept.results[8]), 0.05, 1e-12);
}

TEST(Tracker, BaselinesNeverTakeAKeyframeAfterFailures) {
  hrgbd::OdometryParams p;
  p.method = hrgbd::Method::RansacIcp;
  p.keyframe_after_failures = 1;
  const auto fail = step(0, 0, Status::TooFewInliers);
  const auto run = track({step(0.1), fail, fail, step(0.3)}, p);
  EXPECT_FALSE(run.results[2].keyframe);
  EXPECT_EQ(run.log.aligned.back(), std::make_pair(104.0, 101.0));
}

TEST(Tracker, NoMotionPredictionAfterATimeGapUntilAFrameRegisters) {
  // 1 s apart, then 10 s (a gap: more than prediction_max_gap = 3 times the interval before)
  const std::vector<double> times{100, 101, 102, 112, 113, 114};
  const auto fail = step(0, 0, Status::TooFewInliers);
  const auto script =
      std::deque<hrgbd::RegistrationResult>{step(0.1), step(0.1), fail, step(0.1), step(0.1)};
  const auto run = track(script, {}, times);
  // 112 and 113 (after the gap, nothing registered yet) come without one, 114 with one again
  EXPECT_EQ(run.log.guessed, (std::vector<bool>{true, true, false, false, true}));
  hrgbd::OdometryParams always;
  always.prediction_max_gap = 0;
  EXPECT_EQ(track(script, always, times).log.guessed, std::vector<bool>(5, true));

  // the frame after the gap registers (0.25 m): that motion spans the gap and is no frame's
  // motion, so the flagged frame 113 is predicted with the one before the gap, 0.1 m
  const auto bridged = track({step(0.1), step(0.1), step(0.25), fail}, {}, times);
  EXPECT_EQ(bridged.log.guessed, (std::vector<bool>{true, true, false, true}));
  EXPECT_NEAR(x(bridged.results[4]), 0.2 + 0.25 + 0.1, 1e-12);

  // a flagged frame taken as the keyframe after the gap: the frames after it are predicted again
  hrgbd::OdometryParams after_failures;
  after_failures.keyframe_after_failures = 2;
  const auto resumed = track({step(0.1), step(0.1), fail, fail, step(0.01)}, after_failures, times);
  EXPECT_TRUE(resumed.results[4].keyframe);
  EXPECT_EQ(resumed.log.guessed, (std::vector<bool>{true, true, false, false, true}));
}

TEST(Tracker, OneShortIntervalMakesNoGapOfTheNext) {
  // 1 s apart, one frame 0.01 s after its predecessor (a jittered stamp), then 1 s again: the
  // running mean of the intervals (0.8) does not make the 1 s a gap
  const std::vector<double> times{100, 101, 102, 103, 103.01, 104.01};
  const auto run = track({step(0.1), step(0.1), step(0.1), step(0), step(0.1)}, {}, times);
  EXPECT_EQ(run.log.guessed, std::vector<bool>(5, true));
}

TEST(Tracker, APredictionGapOfAtMostOneIntervalIsRejected) {
  hrgbd::OdometryParams p;
  for (const double ok : {0.0, 1.5, 3.0}) {
    p.prediction_max_gap = ok;
    EXPECT_NO_THROW(p.validate("Odometry")) << ok;
  }
  for (const double bad : {0.5, 1.0}) {
    p.prediction_max_gap = bad;
    try {
      p.validate("Odometry");
      ADD_FAILURE() << "prediction_max_gap = " << bad << " accepted";
    } catch (const hrgbd::ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find("[Odometry] prediction_max_gap"), std::string::npos)
          << e.what();
    }
  }
}

TEST(Tracker, FramesCarryTheVelocityOnceItIsMeasured) {
  // 0.5 s apart; the second registered frame measures 0.1 m and 10 deg a frame: 0.2 m/s, 20 deg/s
  const std::vector<double> times{100, 100.5, 101, 101.5, 102, 112, 112.5, 113};
  const auto fail = step(0, 0, Status::TooFewInliers);
  hrgbd::OdometryParams frame_to_frame;
  frame_to_frame.keyframe_max_translation = 0;
  const auto run =
      track({step(0.1, 10), step(0.1, 10), fail, step(0.2, 20), step(0.1), step(0.1), step(0.1)},
            frame_to_frame, times);
  const auto& v = run.log.velocities;
  ASSERT_EQ(v.size(), 7u);
  // frame 1 (nothing measured yet) and its reference, the first frame: none
  EXPECT_TRUE(v[0].first.hasNaN() && v[0].second.hasNaN());
  // frame 2 has frame 1's motion: translation [m/s] and rotation vector [rad/s], camera frame
  Eigen::Matrix<double, 6, 1> expected;
  expected << 0.2, 0, 0, 0, 20 * M_PI / 180, 0;
  EXPECT_TRUE(v[1].first.isApprox(expected, 1e-9)) << v[1].first.transpose();
  // and so has its reference, frame 1, which measured it when it was registered
  EXPECT_TRUE(v[1].second.isApprox(expected, 1e-9)) << v[1].second.transpose();
  // frame 3 fails: the velocity is forgotten until two frames in a row register again (4 and
  // 5, but 5 comes after a 10 s gap; after it the mean interval, 2.4 s, makes 0.5 s look like a
  // jittered stamp until it has come down again)
  EXPECT_TRUE(v[2].first.isApprox(expected, 1e-9));
  for (int i : {3, 4, 5, 6}) EXPECT_TRUE(v[i].first.hasNaN()) << i;
}

TEST(Tracker, AKeyframeWithoutVelocityGetsTheFirstMeasuredAndJitterIsBounded) {
  // keyframe tracking: the first frame stays the reference; it gets the velocity measured by
  // frame 1 (1 cm in 0.5 s); frame 3 comes 1 ms after frame 2 (a jittered stamp): its 1 cm
  // measures no velocity (10 m/s), frame 4 keeps frame 2's
  const std::vector<double> times{100, 100.5, 101, 101.001, 101.5};
  const auto run = track({step(0.01), step(0.02), step(0.03), step(0.04)}, {}, times);
  const auto& v = run.log.velocities;
  ASSERT_EQ(v.size(), 4u);
  EXPECT_TRUE(v[0].second.hasNaN());              // frame 1: nothing measured yet
  EXPECT_NEAR(v[1].second(0), 0.01 / 0.5, 1e-9);  // frame 2: the first frame's, filled in
  EXPECT_NEAR(v[3].first(0), 0.01 / 0.5, 1e-9);
}
