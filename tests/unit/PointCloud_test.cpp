// Geometric path pre-processing (paper III-C, III-D): down-sampling and normals.
#include "rgbd_odometry/PointCloud.h"

#include <gtest/gtest.h>

#include "SyntheticClouds.h"

using namespace hrgbd;

namespace {
RgbdImage constantDepth(float z) {
  RgbdImage im;
  im.depth = cv::Mat(480, 640, CV_32F, cv::Scalar(z));
  im.grey = cv::Mat(480, 640, CV_8U, cv::Scalar(128));
  return im;
}
}  // namespace

TEST(PointCloud, DownsamplesToAboutTheTargetAndCropsFarPoints) {
  auto im = constantDepth(2.0f);
  im.depth.colRange(0, 160).setTo(6.0f);  // beyond 5 m: dropped (III-C)
  GeometricParams p;
  const auto c = downsampleDepth(im, p);
  EXPECT_EQ(c.input_points, 240u * 240u);  // stride 2: 480 columns of 640 kept, 240 x 240
  EXPECT_NEAR(double(c.points.size()), p.target_points, 0.1 * p.target_points);
  for (const auto& q : c.points) EXPECT_LE(q.z(), 5.0f);
  // Pixel spacing at 2 m with stride 2: 2 * 2 / 525 m.
  EXPECT_NEAR(c.mean_spacing, 4.0 / 525, 1e-4);
}

TEST(PointCloud, RadiusFollowsTheSceneSize) {
  GeometricParams p;
  const auto near = downsampleDepth(constantDepth(1.0f), p);
  const auto far = downsampleDepth(constantDepth(3.0f), p);
  // Same pixels, 9x the area: the cell grows 3x for the same number of points.
  EXPECT_NEAR(far.radius / near.radius, 3.0, 0.3);
  EXPECT_NEAR(double(far.points.size()), double(near.points.size()), 0.15 * p.target_points);
}

TEST(PointCloud, NoDepthGivesAnEmptyCloud) {
  const auto c = downsampleDepth(constantDepth(0.0f), GeometricParams{});
  EXPECT_TRUE(c.points.empty());
  EXPECT_EQ(c.input_points, 0u);
}

TEST(PointCloud, NormalsOfATiltedPlaneFaceTheCamera) {
  const auto pts = test::withNoise(test::tiltedPlane(2.0, 0.5, 0.5, 0.02), 0.002, 1);
  const PointKdTree tree(pts);
  const auto n = estimateNormals(pts, tree, 0.08);
  const Eigen::Vector3f truth = Eigen::Vector3f(0.5f, 0, -1).normalized();  // towards camera
  for (const auto& v : n) EXPECT_GT(v.dot(truth), std::cos(mrpt::DEG2RAD(3.0))) << v.transpose();
}

TEST(PointCloud, LargeNeighbourhoodBendsNormalsOnlyNearEdges) {
  const double dist = 1.5, radius = 0.08;
  const auto pts = test::boxCorner(0.4, 0.02, dist);
  const PointKdTree tree(pts);
  const auto n = estimateNormals(pts, tree, radius);
  const Eigen::Matrix3f R = test::cornerRotation().cast<float>();
  int near_edges = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    float best = -1;  // cosine to the closest face normal (outward: -axis, rotated)
    for (int k = 0; k < 3; ++k) best = std::max(best, n[i].dot(-R.col(k)));
    const double d = test::distanceToCornerEdge(pts[i], dist);
    if (d > radius + 0.01) {
      EXPECT_GT(best, std::cos(mrpt::DEG2RAD(1.0)));  // on a face: the face's normal
    } else if (d < 0.005) {
      EXPECT_LT(best, std::cos(mrpt::DEG2RAD(10.0)));  // on an edge: between two faces
      ++near_edges;
    }
  }
  EXPECT_GT(near_edges, 50);
}

TEST(PointCloud, KdTreeFindsNeighboursAndTheNearestPoint) {
  const auto pts = test::tiltedPlane(1.0, 0.0, 0.1, 0.05);  // 5 x 5 grid
  const PointKdTree tree(pts);
  std::vector<std::pair<std::size_t, float>> nbrs;
  tree.radiusSearch(Eigen::Vector3f(0, 0, 1), 0.051f, nbrs);
  EXPECT_EQ(nbrs.size(), 5u);  // itself and its 4 grid neighbours
  std::size_t i;
  float d2;
  ASSERT_TRUE(tree.nearest(Eigen::Vector3f(0.049f, 0.1f, 1.0f), i, d2));
  EXPECT_NEAR(pts[i].x(), 0.05f, 1e-6);
  EXPECT_NEAR(d2, 1e-6f, 1e-7f);
}
