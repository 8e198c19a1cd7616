// SHOT descriptors: local frame, invariance, noise stability, distinctiveness on a real pair.
#include "rgbd_odometry/ShotDescriptor.h"

#include <gtest/gtest.h>

#include "SyntheticClouds.h"
#include "rgbd_core/Trajectory.h"
#include "rgbd_io/RawlogSource.h"
#include "rgbd_odometry/GeometricFeatures.h"
#include "rgbd_odometry/Is3dSampling.h"

using namespace hrgbd;

namespace {
// A box corner with a floating patch in front, jittered by 1 mm: like sensor data, no point
// sits exactly on a local frame's symmetry plane (where the sign disambiguation is a tie).
Points testScene() {
  auto p = test::boxCorner(0.5, 0.015, 1.5);
  for (auto q : test::tiltedPlane(1.2, 0.0, 0.05, 0.015))
    p.push_back(q + Eigen::Vector3f(0.15f, 0.05f, 0.0f));
  return test::withNoise(p, 0.001, 1);
}
// The IS3D points of a cloud, as the pipeline describes them.
std::vector<std::size_t> is3dKeypoints(const Points& pts) {
  const PointKdTree tree(pts);
  return sampleIs3d(estimateNormals(pts, tree, 0.05), GeometricParams{}).indices;
}
std::vector<std::size_t> everyNth(std::size_t size, std::size_t n) {
  std::vector<std::size_t> k;
  for (std::size_t i = 0; i < size; i += n) k.push_back(i);
  return k;
}
ShotResult shotOf(const Points& pts, const std::vector<std::size_t>& keys) {
  const PointKdTree tree(pts);
  return computeShot(pts, estimateNormals(pts, tree, 0.05), tree, keys, 0.12, 10);
}
}  // namespace

TEST(ShotDescriptor, LocalFrameIsARightHandedRotation) {
  const auto pts = testScene();
  const PointKdTree tree(pts);
  std::vector<std::pair<std::size_t, float>> nbrs;
  tree.radiusSearch(pts[100], 0.12f, nbrs);
  Eigen::Matrix3f F;
  ASSERT_TRUE(shotLocalFrame(pts, nbrs, pts[100], 0.12f, F));
  EXPECT_TRUE((F.transpose() * F).isIdentity(1e-5f));
  EXPECT_NEAR(F.determinant(), 1.0f, 1e-5f);
}

TEST(ShotDescriptor, RowsAreUnitLength352Values) {
  const auto pts = testScene();
  const auto s = shotOf(pts, everyNth(pts.size(), 50));
  ASSERT_GT(s.descriptors.rows, 20);
  EXPECT_EQ(s.descriptors.cols, kShotLength);
  EXPECT_EQ(std::size_t(s.descriptors.rows), s.kept.size());
  for (int i = 0; i < s.descriptors.rows; ++i)
    EXPECT_NEAR(cv::norm(s.descriptors.row(i)), 1.0, 1e-5);
}

TEST(ShotDescriptor, InvariantToRigidMotion) {
  const auto pts = testScene();
  const auto keys = everyNth(pts.size(), 37);
  Eigen::Isometry3f T = Eigen::Isometry3f::Identity();
  T.linear() = Eigen::AngleAxisf(0.3f, Eigen::Vector3f(0.2f, 1, 0.1f).normalized()).matrix();
  T.translation() = Eigen::Vector3f(0.1f, -0.05f, 0.2f);
  const auto a = shotOf(pts, keys);
  const auto b = shotOf(test::transformed(pts, T), keys);
  ASSERT_EQ(a.kept, b.kept);
  // Normals are re-estimated on the moved cloud (oriented to the camera, which did not move),
  // so only the numerics differ.
  EXPECT_LT(cv::norm(a.descriptors, b.descriptors, cv::NORM_INF), 0.02);
}

TEST(ShotDescriptor, NearestNeighbourSurvivesSensorNoise) {
  const auto pts = testScene();
  const auto keys = is3dKeypoints(pts);
  const auto clean = shotOf(pts, keys);
  const auto noisy = shotOf(test::withNoise(pts, 0.002, 7), keys);
  ASSERT_EQ(clean.kept, noisy.kept);
  cv::Mat dist;
  cv::batchDistance(noisy.descriptors, clean.descriptors, dist, CV_32F, cv::noArray(), cv::NORM_L2);
  // Along an edge, neighbouring keypoints look alike to any local descriptor: count a nearest
  // descriptor within 2 cm of the keypoint itself as correct.
  // `chance`: the expected count if the nearest descriptor were a random keypoint.
  int correct = 0;
  double chance = 0;
  for (int i = 0; i < dist.rows; ++i) {
    cv::Point best;
    cv::minMaxLoc(dist.row(i), nullptr, nullptr, &best);
    const auto& self = pts[clean.kept[i]];
    correct += (pts[clean.kept[best.x]] - self).norm() < 0.02f;
    for (const auto k : clean.kept) chance += (pts[k] - self).norm() < 0.02f ? 1.0 / dist.rows : 0;
  }
  // Measured: 161 of 350 (46 %); chance would give 5.5 (1.6 %).
  EXPECT_GT(correct, dist.rows * 35 / 100) << correct << " of " << dist.rows;
  EXPECT_GT(correct, 5 * chance) << chance;
}

TEST(ShotDescriptor, MatchesOnTheBundledDeskPairAreMostlyCorrect) {
  // Two consecutive frames of the bundled simulated desk with their exact ground truth: of the
  // source keypoints that have a target keypoint within 1.5 cm (under the true motion), how many
  // have a nearest descriptor within 3 cm of the true position?
  const std::string stem = std::string(HRGBD_SOURCE_DIR) + "/rawlogs/desk_near";
  RawlogSource src(stem + ".rawlog");
  const auto gt = loadTumTrajectory(stem + "_groundtruth.txt");
  const auto a = prepareRgbdImage(*src.next()), b = prepareRgbdImage(*src.next());
  const GeometricParams p;
  const auto fa = extractGeometricFeatures(a, p).features;
  const auto fb = extractGeometricFeatures(b, p).features;
  const auto rel = (gt[1].pose - gt[0].pose).getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>();
  Eigen::Isometry3d T;  // b -> a
  T.matrix() = rel.asEigen();
  cv::Mat dist;
  cv::batchDistance(fb.descriptors, fa.descriptors, dist, CV_32F, cv::noArray(), cv::NORM_L2);
  int repeatable = 0, correct = 0;
  double chance = 0;
  for (std::size_t i = 0; i < fb.size(); ++i) {
    const Eigen::Vector3d truth = T * fb.points[i];
    bool has_counterpart = false;
    for (const auto& q : fa.points) has_counterpart |= (truth - q).norm() < 0.015;
    if (!has_counterpart) continue;
    ++repeatable;
    cv::Point best;
    cv::minMaxLoc(dist.row(int(i)), nullptr, nullptr, &best);
    correct += (fa.points[best.x] - truth).norm() < 0.03;
    for (const auto& q : fa.points) chance += (q - truth).norm() < 0.03 ? 1.0 / fa.size() : 0;
  }
  // Measured: 69 of 222 (31 %); chance would give 3.0 (1.4 %).
  ASSERT_GT(repeatable, 100);
  EXPECT_GT(correct, repeatable / 4) << correct << " of " << repeatable;
  EXPECT_GT(correct, 5 * chance) << chance;
}
