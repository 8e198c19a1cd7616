// The renderer against its own ground truth: depth back-projected from one frame with the true
// poses must land on the depth seen by another frame, within the sensor's noise.
#include "rgbd_sim/Simulator.h"

#include <algorithm>
#include <fstream>

#include "TestData.h"

using namespace hrgbd::sim;

TEST(Simulator, TwoFramesOverlapWithinTheNoiseLevel) {
  SimParams p;
  p.scene = "desk";
  const auto scene = makeScene(p.scene, false);
  const SimCamera cam;
  const auto path = cameraPath(scene, p, {0.0, 0.5});
  std::mt19937 rng(3);
  cv::Mat bgr[2], depth[2];
  for (int i = 0; i < 2; ++i)
    applyKinectModel(renderIdeal(scene, path[i].pose, cam), scene, cam, path[i].pose, path[i].pose,
                     1.0, p.sensor, 5000, rng, bgr[i], depth[i]);
  ASSERT_GT((path[1].pose - path[0].pose).norm(), 0.05);  // the camera really moved

  std::vector<double> rel;  // relative depth differences
  for (int v = 0; v < cam.height; v += 4)
    for (int u = 0; u < cam.width; u += 4) {
      const double z = depth[0].at<uint16_t>(v, u) / 5000.0;
      if (z <= 0) continue;
      const mrpt::math::TPoint3D pc((u - cam.cx) * z / cam.fx, (v - cam.cy) * z / cam.fy, z);
      const auto q = path[1].pose.inverseComposePoint(path[0].pose.composePoint(pc));
      const int u1 = static_cast<int>(std::lround(cam.fx * q.x / q.z + cam.cx));
      const int v1 = static_cast<int>(std::lround(cam.fy * q.y / q.z + cam.cy));
      if (u1 < 0 || v1 < 0 || u1 >= cam.width || v1 >= cam.height) continue;
      const double z1 = depth[1].at<uint16_t>(v1, u1) / 5000.0;
      if (z1 > 0) rel.push_back(std::abs(z1 - q.z) / q.z);
    }
  ASSERT_GT(rel.size(), 5000u);
  std::sort(rel.begin(), rel.end());
  // Kinect noise at 1-2 m is ~0.3-1 % of the depth; occlusions and edges make the tail.
  EXPECT_LT(rel[rel.size() / 2], 0.01);
  EXPECT_LT(rel[rel.size() * 8 / 10], 0.025);
  // And a wrong pose (5 cm further along the view, world y here) must not overlap as well.
  auto shifted = path[1].pose;
  shifted.y_incr(0.05);
  int close = 0, n = 0;
  for (int v = 0; v < cam.height; v += 8)
    for (int u = 0; u < cam.width; u += 8) {
      const double z = depth[0].at<uint16_t>(v, u) / 5000.0;
      if (z <= 0) continue;
      const mrpt::math::TPoint3D pc((u - cam.cx) * z / cam.fx, (v - cam.cy) * z / cam.fy, z);
      const auto q = shifted.inverseComposePoint(path[0].pose.composePoint(pc));
      const int u1 = static_cast<int>(std::lround(cam.fx * q.x / q.z + cam.cx));
      const int v1 = static_cast<int>(std::lround(cam.fy * q.y / q.z + cam.cy));
      if (u1 < 0 || v1 < 0 || u1 >= cam.width || v1 >= cam.height) continue;
      const double z1 = depth[1].at<uint16_t>(v1, u1) / 5000.0;
      if (z1 > 0) ++n, close += std::abs(z1 - q.z) / q.z < 0.01;
    }
  EXPECT_LT(static_cast<double>(close) / n, 0.5);
}

TEST(Simulator, DepthIsQuantisedInDisparity) {
  // Depth steps grow with the square of the distance: at 2 m a 1/8 px step is ~1.3 cm.
  SimParams p;
  p.scene = "wall";
  p.far = true;
  const auto scene = makeScene(p.scene, true);
  const SimCamera cam;
  const auto pose = cameraPath(scene, p, {0.0})[0].pose;
  std::mt19937 rng(1);
  cv::Mat bgr, depth;
  applyKinectModel(renderIdeal(scene, pose, cam), scene, cam, pose, pose, 1.0, p.sensor, 5000, rng,
                   bgr, depth);
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
  const auto a = simulate(p, {dir + "/a.rawlog", "", hrgbd::ImageStorage::Inline});
  const auto b = simulate(p, {dir + "/b.rawlog", "", hrgbd::ImageStorage::Inline});
  std::ifstream fa(dir + "/a.rawlog", std::ios::binary), fb(dir + "/b.rawlog", std::ios::binary);
  const std::string sa{std::istreambuf_iterator<char>(fa), {}},
      sb{std::istreambuf_iterator<char>(fb), {}};
  EXPECT_EQ(sa, sb);
  EXPECT_EQ(a.ground_truth.size(), 2u);
}
