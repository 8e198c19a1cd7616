// IS3D sampling (paper III-E, Algorithm 1) on synthetic clouds with known structure.
#include "rgbd_odometry/Is3dSampling.h"

#include <gtest/gtest.h>

#include "SyntheticClouds.h"

using namespace hrgbd;

namespace {
Points normalsOf(const Points& pts, double radius) {
  const PointKdTree tree(pts);
  return estimateNormals(pts, tree, radius);
}
}  // namespace

TEST(Is3dSampling, APlaneYieldsAlmostNoPoints) {
  const auto pts = test::withNoise(test::tiltedPlane(2.0, 0.3, 0.6, 0.02), 0.003, 2);
  const auto r = sampleIs3d(normalsOf(pts, 0.08), GeometricParams{});
  ASSERT_EQ(r.groups.size(), 1u);
  EXPECT_LT(r.indices.size(), pts.size() / 50) << "of " << pts.size();
  EXPECT_LT(r.groups[0].sigma_deg, 2.0);
}

TEST(Is3dSampling, BoxCornerKeepsTheEdgesAndDropsTheFaces) {
  const double dist = 1.5, radius = 0.08;
  const auto pts = test::withNoise(test::boxCorner(0.5, 0.02, dist), 0.002, 5);
  GeometricParams p;
  const auto r = sampleIs3d(normalsOf(pts, radius), p);
  EXPECT_EQ(r.groups.size(), 3u);  // one dominant orientation per face
  ASSERT_GT(r.indices.size(), 50u);
  EXPECT_LE(r.indices.size(), std::size_t(p.is3d_points));
  std::size_t near_edge = 0;
  for (const auto i : r.indices) near_edge += test::distanceToCornerEdge(pts[i], dist) < radius;
  EXPECT_GT(near_edge, r.indices.size() * 95 / 100);
}

TEST(Is3dSampling, ZigZagKeepsTheFolds) {
  const double period = 0.3, radius = 0.06;
  const auto pts = test::withNoise(test::zigZag(2.0, 0.075, period, 0.9, 0.02), 0.002, 3);
  const auto r = sampleIs3d(normalsOf(pts, radius), GeometricParams{});
  EXPECT_EQ(r.groups.size(), 2u);  // the two panel orientations (+-45 deg)
  ASSERT_GT(r.indices.size(), 100u);
  std::size_t near_fold = 0;
  for (const auto i : r.indices) near_fold += test::distanceToFold(pts[i].x(), period) < radius;
  EXPECT_GT(near_fold, r.indices.size() * 95 / 100);
}

TEST(Is3dSampling, SameSeedSameResultAndTheCapHolds) {
  const auto pts = test::withNoise(test::zigZag(2.0, 0.075, 0.3, 0.9, 0.02), 0.002, 4);
  const auto n = normalsOf(pts, 0.06);
  GeometricParams p;
  p.is3d_points = 40;
  const auto a = sampleIs3d(n, p), b = sampleIs3d(n, p);
  EXPECT_EQ(a.indices, b.indices);
  EXPECT_EQ(a.indices.size(), 40u);
  EXPECT_GT(a.candidates, 40u);
}
