#pragma once
// Synthetic correspondences with a known rigid motion, Gaussian noise and random outliers.
#include <random>

#include "rgbd_odometry/RigidFit.h"

namespace hrgbd::test {

inline Eigen::Isometry3d knownMotion() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = (Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(-0.03, Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  T.translation() = Eigen::Vector3d(0.04, -0.01, 0.03);
  return T;
}

/** n pairs, points in a frustum-like box at 1-4 m; `outlier_ratio` of targets replaced by
 * random points of the same box; `noise` [m] std on each coordinate of the targets. */
inline Correspondences makeCorrespondences(const Eigen::Isometry3d& T, int n, double noise,
                                           double outlier_ratio, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> ux(-1.5, 1.5), uy(-1.0, 1.0), uz(1.0, 4.0), u01(0, 1);
  std::normal_distribution<double> g(0, noise > 0 ? noise : 1);
  Correspondences c;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d p(ux(rng), uy(rng), uz(rng));
    Eigen::Vector3d q = T * p;
    if (noise > 0) q += Eigen::Vector3d(g(rng), g(rng), g(rng));
    if (u01(rng) < outlier_ratio) q = Eigen::Vector3d(ux(rng), uy(rng), uz(rng));
    c.source.push_back(p);
    c.target.push_back(q);
  }
  return c;
}

inline double rotationErrorDeg(const Eigen::Isometry3d& A, const Eigen::Isometry3d& B) {
  return Eigen::AngleAxisd(A.rotation().transpose() * B.rotation()).angle() * 180.0 / M_PI;
}
inline double translationError(const Eigen::Isometry3d& A, const Eigen::Isometry3d& B) {
  return (A.translation() - B.translation()).norm();
}

}  // namespace hrgbd::test
