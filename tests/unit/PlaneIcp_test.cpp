// Point-to-plane refinement of the geometric path on synthetic clouds with known motion.
#include "rgbd_odometry/PlaneIcp.h"

#include <gtest/gtest.h>

#include "SyntheticClouds.h"

using namespace hrgbd;

namespace {
double angleDeg(const Eigen::Isometry3d& T) {
  return mrpt::RAD2DEG(Eigen::AngleAxisd(T.rotation()).angle());
}
}  // namespace

TEST(PlaneIcp, ConvergesOnABoxCornerFromIdentity) {
  const auto target = test::boxCorner(0.5, 0.01, 1.5);
  const PointKdTree tree(target);
  const auto normals = estimateNormals(target, tree, 0.03);
  Eigen::Isometry3f motion = Eigen::Isometry3f::Identity();  // source -> target
  motion.linear() = Eigen::AngleAxisf(0.03f, Eigen::Vector3f(0.3f, 1, 0.2f).normalized()).matrix();
  motion.translation() = Eigen::Vector3f(0.01f, -0.015f, 0.01f);
  const auto source = test::transformed(test::boxCorner(0.5, 0.013, 1.5), motion.inverse());
  const auto r =
      refinePointToPlane(source, target, normals, tree, Eigen::Isometry3d::Identity(), 30, 0.05);
  const Eigen::Isometry3d err = motion.cast<double>().inverse() * r.T;
  EXPECT_TRUE(r.converged);
  EXPECT_LT(err.translation().norm(), 0.001);
  EXPECT_LT(angleDeg(err), 0.05);
  EXPECT_LT(r.rms, 0.001);
}

TEST(PlaneIcp, ASinglePlaneLeavesTheSlidingDirectionsAtTheInitialGuess) {
  const auto target = test::tiltedPlane(2.0, 0.0, 0.5, 0.02);
  const PointKdTree tree(target);
  const auto normals = estimateNormals(target, tree, 0.06);
  Eigen::Isometry3d initial = Eigen::Isometry3d::Identity();
  initial.translation() = Eigen::Vector3d(0.01, 0.0, 0.02);  // 1 cm along, 2 cm off the plane
  const auto r = refinePointToPlane(target, target, normals, tree, initial, 30, 0.05);
  EXPECT_NEAR(r.T.translation().z(), 0.0, 0.001);   // the plane fixes its normal direction
  EXPECT_NEAR(r.T.translation().x(), 0.01, 0.002);  // and nothing else: no drift
  EXPECT_NEAR(r.T.translation().y(), 0.0, 0.002);
}

TEST(PlaneIcp, NoPairsWithinReachKeepsTheInitialGuess) {
  const auto target = test::tiltedPlane(2.0, 0.0, 0.2, 0.02);
  const PointKdTree tree(target);
  const auto normals = estimateNormals(target, tree, 0.06);
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation() = Eigen::Vector3d(0, 0, 1.0);
  const auto r = refinePointToPlane(target, target, normals, tree, far, 10, 0.05);
  EXPECT_EQ(r.pairs, 0u);
  EXPECT_FALSE(r.converged);
  EXPECT_TRUE(r.T.isApprox(far));
}
