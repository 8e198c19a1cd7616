// The renderer against its own ground truth: depth back-projected from one frame with the true
// poses must land on the depth seen by another frame, within the sensor's noise.
#include "rgbd_sim/Simulator.h"

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <fstream>

#include "TestData.h"
#include "rgbd_core/Config.h"
#include "rgbd_io/TumSource.h"

using namespace hrgbd::sim;

namespace {
// Relative depth differences |z_b - z| / z of frame A's depth pixels (every `step`-th) seen from
// pose B, where frame B has depth.
std::vector<double> depthAgreement(const cv::Mat& depth_a, const mrpt::poses::CPose3D& pose_a,
                                   const cv::Mat& depth_b, const mrpt::poses::CPose3D& pose_b,
                                   const hrgbd::PinholeCamera& cam, int step) {
  std::vector<double> rel;
  for (int v = 0; v < cam.height; v += step)
    for (int u = 0; u < cam.width; u += step) {
      const double z = depth_a.at<uint16_t>(v, u) / 5000.0;
      if (z <= 0) continue;
      const mrpt::math::TPoint3D pc((u - cam.cx) * z / cam.fx, (v - cam.cy) * z / cam.fy, z);
      const auto q = pose_b.inverseComposePoint(pose_a.composePoint(pc));
      const int u1 = static_cast<int>(std::lround(cam.fx * q.x / q.z + cam.cx));
      const int v1 = static_cast<int>(std::lround(cam.fy * q.y / q.z + cam.cy));
      if (u1 < 0 || v1 < 0 || u1 >= cam.width || v1 >= cam.height) continue;
      const double z1 = depth_b.at<uint16_t>(v1, u1) / 5000.0;
      if (z1 > 0) rel.push_back(std::abs(z1 - q.z) / q.z);
    }
  return rel;
}
}  // namespace

TEST(Simulator, TwoFramesOverlapWithinTheNoiseLevel) {
  SimParams p;
  p.scene = "desk";
  const auto scene = makeScene(p.scene, false);
  const hrgbd::PinholeCamera cam;
  const auto path = cameraPath(scene, p, {0.0, 0.5});
  std::mt19937 rng(3);
  cv::Mat depth[2];
  for (int i = 0; i < 2; ++i)
    depth[i] = applyKinectModel(renderIdeal(scene, path[i].pose, cam), cam,
                                {path[i].pose, path[i].pose, 1.0, 5000}, p.sensor, rng)
                   .depth;
  ASSERT_GT((path[1].pose - path[0].pose).norm(), 0.05);  // the camera really moved

  auto rel = depthAgreement(depth[0], path[0].pose, depth[1], path[1].pose, cam, 4);
  ASSERT_GT(rel.size(), 5000u);
  std::sort(rel.begin(), rel.end());
  // Kinect noise at 1-2 m is ~0.3-1 % of the depth; occlusions and edges make the tail.
  EXPECT_LT(rel[rel.size() / 2], 0.01);
  EXPECT_LT(rel[rel.size() * 8 / 10], 0.025);
  // And a wrong pose (5 cm further along the view, world y here) must not overlap as well.
  auto shifted = path[1].pose;
  shifted.y_incr(0.05);
  const auto wrong = depthAgreement(depth[0], path[0].pose, depth[1], shifted, cam, 8);
  const auto close = std::count_if(wrong.begin(), wrong.end(), [](double r) { return r < 0.01; });
  const auto n = wrong.size();
  EXPECT_LT(static_cast<double>(close) / n, 0.5);
}

TEST(Simulator, DepthIsQuantisedInDisparity) {
  // Depth steps grow with the square of the distance: at 2 m a 1/8 px step is ~1.3 cm.
  SimParams p;
  p.scene = "wall";
  p.far = true;
  const auto scene = makeScene(p.scene, true);
  const hrgbd::PinholeCamera cam;
  const auto pose = cameraPath(scene, p, {0.0})[0].pose;
  std::mt19937 rng(1);
  const cv::Mat depth =
      applyKinectModel(renderIdeal(scene, pose, cam), cam, {pose, pose, 1.0, 5000}, p.sensor, rng)
          .depth;
  std::vector<uint16_t> values;
  for (int u = 0; u < cam.width; ++u)
    if (depth.at<uint16_t>(240, u)) values.push_back(depth.at<uint16_t>(240, u));
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  ASSERT_GE(values.size(), 2u);
  int min_step = 1 << 30;
  for (size_t i = 1; i < values.size(); ++i)
    min_step = std::min(min_step, values[i] - values[i - 1]);
  EXPECT_GT(min_step / 5000.0, 0.008);  // no depth values in between the disparity steps
  EXPECT_LT(values.size(), 60u);        // a few dozen levels, not a continuum
}

TEST(Simulator, SameSeedSameFrames) {
  SimParams p;
  p.frames = 2;
  const auto dir = hrgbd::test::tempDir("sim_seed");
  const auto a = simulate(p, {dir + "/a.rawlog", "", hrgbd::ImageStorage::Inline, ""});
  const auto b = simulate(p, {dir + "/b.rawlog", "", hrgbd::ImageStorage::Inline, ""});
  std::ifstream fa(dir + "/a.rawlog", std::ios::binary), fb(dir + "/b.rawlog", std::ios::binary);
  const std::string sa{std::istreambuf_iterator<char>(fa), {}},
      sb{std::istreambuf_iterator<char>(fb), {}};
  EXPECT_EQ(sa, sb);
  EXPECT_EQ(a.ground_truth.size(), 2u);
  EXPECT_EQ(a.sparse_depth_frames, 0);  // the sweep sees the desk
}

TEST(Simulator, FramesThatLookPastTheSceneAreCounted) {
  // A camera turning all round in place, 30 deg a frame, replayed over the plain wall (put ahead
  // of its first frame): facing the wall, its depth fills the image; facing away, it sees
  // nothing. rgbd-simulate warns with the count.
  hrgbd::Trajectory spin;
  for (int i = 0; i <= 12; ++i) {
    const double a = mrpt::DEG2RAD(30.0 * i);
    const Eigen::Vector3d eye(0, 0, 1);
    spin.push_back({i / 30.0, lookAt(eye, eye + Eigen::Vector3d(std::cos(a), std::sin(a), 0))});
  }
  const auto dir = hrgbd::test::tempDir("sim_spin");
  hrgbd::saveTumTrajectory(dir + "/spin.txt", spin);
  SimParams p;
  p.scene = "wall";
  p.frames = 12;
  p.motion = dir + "/spin.txt";
  const auto r = simulate(p, {dir + "/spin.rawlog", "", hrgbd::ImageStorage::Inline, ""});
  EXPECT_GT(r.sparse_depth_frames, 0);
  EXPECT_LT(r.sparse_depth_frames, 12);
}

TEST(Simulator, ATumFolderSaysItsCameraWhateverItsName) {
  SimParams p;
  p.frames = 2;
  // a name that would make TumSource guess the fr1 Kinect (its intrinsics and rolling shutter)
  const auto dir = hrgbd::test::tempDir("sim_fr1_desk") + "/tum";
  simulate(p, {"", dir, hrgbd::ImageStorage::Inline, ""});
  hrgbd::TumSource src(dir);
  const auto obs = src.next();
  ASSERT_TRUE(obs);
  const hrgbd::PinholeCamera sim;
  EXPECT_EQ(obs->cameraParamsIntensity.fx(), sim.fx);
  EXPECT_EQ(obs->cameraParamsIntensity.fy(), sim.fy);
  EXPECT_EQ(obs->cameraParamsIntensity.cx(), sim.cx);
  EXPECT_EQ(obs->cameraParamsIntensity.cy(), sim.cy);
  EXPECT_EQ(src.rollingShutterMs(), 0);
  EXPECT_NE(src.describe().find("calibration.txt"), std::string::npos) << src.describe();
}

TEST(Simulator, SensorModelKeysAreReadAndChecked) {
  mrpt::config::CConfigFileMemory ini;
  ini.write("Simulator", "correlation_window", 5);
  ini.write("Simulator", "rolling_shutter_ms", 12.5);
  SimParams p;
  p.loadFromConfigFile(ini, "Simulator");
  EXPECT_EQ(p.sensor.correlation_window, 5);
  EXPECT_DOUBLE_EQ(p.sensor.rolling_shutter_ms, 12.5);
  ini.write("Simulator", "correlation_window", 0);
  EXPECT_THROW(p.loadFromConfigFile(ini, "Simulator"), hrgbd::ConfigError);
  ini.write("Simulator", "correlation_window", 9);
  ini.write("Simulator", "disparity_distorsion", 0.3);  // misspelt key
  EXPECT_THROW(p.loadFromConfigFile(ini, "Simulator"), hrgbd::ConfigError);
}

TEST(Simulator, EllipsoidDepthIsExact) {
  // The teddy-like object's body (centre (0, 0, 1), radii y 0.18) seen level from 1 m away.
  const auto scene = makeScene("object", false);
  const hrgbd::PinholeCamera cam;
  const auto pose = lookAt(Eigen::Vector3d(0, -1.0, 1.0), Eigen::Vector3d(0, 0, 1.0));
  const auto f = renderIdeal(scene, pose, cam);
  EXPECT_NEAR(f.depth.at<float>(240, 320), 1.0 - 0.18, 1e-3);
  EXPECT_GT(f.incidence.at<float>(240, 320), 0.99);  // seen head-on
}

TEST(Simulator, RollingShutterSeesEachRowFromItsOwnPose) {
  const auto scene = makeScene("desk", false);
  const hrgbd::PinholeCamera cam;
  const auto first = lookAt(Eigen::Vector3d(0, 0.0, 1.2), Eigen::Vector3d(0, 1.3, 0.75));
  const auto last = first + mrpt::poses::CPose3D(0.02, 0, 0, mrpt::DEG2RAD(2.0), 0, 0);
  const auto skewed = renderIdeal(scene, first, cam, last);
  const auto a = renderIdeal(scene, first, cam), b = renderIdeal(scene, last, cam);
  const int bottom = cam.height - 1;
  EXPECT_EQ(cv::norm(skewed.depth.row(0), a.depth.row(0), cv::NORM_INF), 0.0);
  EXPECT_LT(cv::norm(skewed.depth.row(bottom), b.depth.row(bottom), cv::NORM_INF), 1e-4);
  EXPECT_GT(cv::norm(skewed.depth.row(bottom), a.depth.row(bottom), cv::NORM_INF), 0.01);
}

TEST(Simulator, ReplayedMotionLooksAtTheScene) {
  // A hand-held orbit (radius 1.2 m, 90 deg, with a wobble) around a point far from the scene's
  // origin, as a TUM file: replayed, the camera must keep the scene's look_at in view.
  const Eigen::Vector3d centre(5, -3, 0.9);
  hrgbd::Trajectory orbit;
  for (int i = 0; i <= 90; ++i) {
    const double a = mrpt::DEG2RAD(i), r = 1.2 + 0.05 * std::sin(0.3 * i);
    const Eigen::Vector3d eye = centre + Eigen::Vector3d(r * std::cos(a), r * std::sin(a), 0.5);
    orbit.push_back({i * 0.05, lookAt(eye, centre + Eigen::Vector3d(0, 0, 0.02 * std::sin(i)))});
  }
  EXPECT_LT((lookedAtPoint(orbit, 1.0) - centre).norm(), 0.05);
  // Near-parallel axes (pure translation): a point `distance` ahead of the first camera.
  hrgbd::Trajectory slide;
  for (int i = 0; i < 10; ++i)
    slide.push_back(
        {i * 0.1, lookAt(Eigen::Vector3d(0.01 * i, 0, 1), Eigen::Vector3d(0.01 * i, 2, 1))});
  EXPECT_LT((lookedAtPoint(slide, 1.5) - Eigen::Vector3d(0, 1.5, 1)).norm(), 0.05);
  // Sliding +-0.3 m and turning with the slide (up to 8.6 deg, as a hand-held camera does): the
  // least-squares point is 0.58 m behind the cameras (fr1/xyz's 792 frames: 0.28 m, blank frames).
  // The point must be ahead of every camera, inside its image (half width 320 / fx 525 = 0.61).
  hrgbd::Trajectory turning;
  for (int i = 0; i < 200; ++i) {
    const double x = 0.3 * std::sin(0.1 * i);
    const Eigen::Vector3d eye(x, 0, 1);
    turning.push_back(
        {i / 30.0, lookAt(eye, eye + Eigen::Vector3d(std::sin(0.5 * x), std::cos(0.5 * x), 0))});
  }
  const Eigen::Vector3d seen = lookedAtPoint(turning, 1.0);
  for (const auto& q : turning) {
    const auto local =
        q.pose.inverseComposePoint(mrpt::math::TPoint3D(seen.x(), seen.y(), seen.z()));
    EXPECT_GT(local.z, 0.8) << "t = " << q.t;
    EXPECT_LT(std::abs(local.x) / local.z, 0.61) << "t = " << q.t;
  }

  const auto file = hrgbd::test::tempDir("sim_replay") + "/orbit.txt";
  hrgbd::saveTumTrajectory(file, orbit);
  SimParams p;
  p.scene = "object";
  p.motion = file;
  const auto scene = makeScene(p.scene, false);
  std::vector<double> times;
  for (int i = 0; i < 130; ++i) times.push_back(i / 30.0);
  for (const auto& q : cameraPath(scene, p, times)) {
    const auto local = q.pose.inverseComposePoint(
        mrpt::math::TPoint3D(scene.look_at.x(), scene.look_at.y(), scene.look_at.z()));
    EXPECT_NEAR(local.z, 1.2 * std::hypot(1, 0.5 / 1.2), 0.1);  // the real distance
    EXPECT_LT(std::hypot(local.x, local.y) / local.z, 0.05);    // near the optical axis
  }
}

TEST(Simulator, AMotionSampledSlowerThanTheFramesIsInterpolated) {
  // Poses 1 s apart: the window of poses read (up to 0.1 s past the last frame) held only the
  // first, and every frame after it was "cannot interpolate".
  hrgbd::Trajectory slow;
  for (int i = 0; i < 2; ++i)
    slow.push_back(
        {i * 1.0, lookAt(Eigen::Vector3d(0.5 * i, 0, 1), Eigen::Vector3d(0.5 * i, 2, 1))});
  const auto file = hrgbd::test::tempDir("sim_slow_motion") + "/slow.txt";
  hrgbd::saveTumTrajectory(file, slow);
  SimParams p;
  p.motion = file;
  std::vector<double> times;
  for (int i = 0; i < 10; ++i) times.push_back(i / 30.0);
  const auto path = cameraPath(makeScene(p.scene, false), p, times);
  ASSERT_EQ(path.size(), times.size());
  for (std::size_t i = 1; i < path.size(); ++i)  // 0.5 m/s along the slide
    EXPECT_NEAR((path[i].pose - path[0].pose).norm(), 0.5 * times[i], 1e-6);
}

TEST(Simulator, AMotionBeyondTheEvaluatorsRangeIsRefusedNamingThePose) {
  // 1e30 m was replayed as blank frames and written to the ground truth as -2^47 m.
  hrgbd::Trajectory far;
  for (int i = 0; i < 10; ++i)
    far.push_back({i * 0.05, mrpt::poses::CPose3D(0.01 * i, 0, 1, 0, 0, 0)});
  far[3].pose.x(1e30);
  const auto file = hrgbd::test::tempDir("sim_far_motion") + "/far.txt";
  hrgbd::saveTumTrajectory(file, far);
  SimParams p;
  p.motion = file;
  try {
    cameraPath(makeScene(p.scene, false), p, {0.0, 1 / 30.0, 2 / 30.0});
    FAIL() << "a motion with a coordinate of 1e30 m was replayed";
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    for (const auto* part : {"far.txt", "time stamp 0.15", "1e+30 m", "up to 1e9 m"})
      EXPECT_NE(msg.find(part), std::string::npos) << part << ": " << msg;
  }
}

TEST(Simulator, TheLoopMotionReturnsToItsStart) {
  // 90 frames at 30 Hz: one frame after the last the camera is back where it started, having
  // orbited +-35 deg on the way; every pose looks at the scene's look_at.
  SimParams p;
  p.scene = "desk";
  p.motion = "loop";
  p.frames = 90;
  const auto scene = makeScene(p.scene, false);
  std::vector<double> times;
  for (int i = 0; i <= p.frames; ++i) times.push_back(i / p.fps);
  const auto path = cameraPath(scene, p, times);
  ASSERT_EQ(path.size(), times.size());
  EXPECT_LT((path.back().pose - path.front().pose).norm(), 1e-9);
  double widest = 0;
  const Eigen::Vector3d start(path[0].pose.x(), path[0].pose.y(), path[0].pose.z());
  for (const auto& q : path) {
    const Eigen::Vector3d eye(q.pose.x(), q.pose.y(), q.pose.z());
    widest = std::max(
        widest, std::acos(std::clamp(
                    (eye - scene.look_at).normalized().dot((start - scene.look_at).normalized()),
                    -1.0, 1.0)));
    const auto local = q.pose.inverseComposePoint(
        mrpt::math::TPoint3D(scene.look_at.x(), scene.look_at.y(), scene.look_at.z()));
    EXPECT_LT(std::hypot(local.x, local.y) / local.z, 1e-6);  // on the optical axis
  }
  EXPECT_GT(mrpt::RAD2DEG(widest), 25.0);  // 35 deg of azimuth seen from above: 29.9
}

TEST(Simulator, TheWalkerCrossesTheSceneAndComesBack) {
  const auto scene = makeScene("desk", false);  // sweep_axis x
  auto centre_x = [&](double t) {
    const auto s = withWalker(scene, t, 0.5);
    EXPECT_EQ(s.quads.size(), scene.quads.size() + 5);  // a box without a bottom
    const auto& top = s.quads.back();
    return top.origin.x() + 0.5 * top.u.x();
  };
  // 0.8 m either side of look_at, 3.2 s from one end to the other at 0.5 m/s
  EXPECT_NEAR(centre_x(0.0), -0.8, 1e-9);
  EXPECT_NEAR(centre_x(1.6), 0.0, 1e-9);
  EXPECT_NEAR(centre_x(3.2), 0.8, 1e-9);
  EXPECT_NEAR(centre_x(4.8), 0.0, 1e-9);
  EXPECT_NEAR(centre_x(6.4), -0.8, 1e-9);
  EXPECT_NEAR(centre_x(-1.6), 0.0, 1e-9);  // before the start: the same wave
  EXPECT_NEAR(centre_x(-3.2), 0.8, 1e-9);
  // and the camera sees it move: from one pose, the depth changes where it was and where it is
  const hrgbd::PinholeCamera cam;
  const auto pose = lookAt(Eigen::Vector3d(0, 0.3, 1.35), scene.look_at);
  const auto a = renderIdeal(withWalker(scene, 1.0, 0.5), pose, cam);
  const auto b = renderIdeal(withWalker(scene, 2.2, 0.5), pose, cam);
  const auto still = renderIdeal(scene, pose, cam);
  cv::Mat moved = cv::abs(a.depth - b.depth) > 0.05;
  EXPECT_GT(cv::countNonZero(moved), cam.width * cam.height / 50);
  EXPECT_GT(cv::countNonZero(cv::abs(a.depth - still.depth) > 0.05), 0);
}
