#pragma once
/** \file PoseGap.h
 * How far apart two poses are. */
#include <Eigen/Geometry>

namespace hrgbd {

/** The motion between two poses, a^-1 b, as its translation length and rotation angle. */
struct PoseGap {
  double metres = 0;
  double radians = 0;
};

inline PoseGap poseGap(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  const Eigen::Isometry3d d = a.inverse() * b;
  return {d.translation().norm(), Eigen::AngleAxisd(d.rotation()).angle()};
}

/** [m] typical depth of what a camera sees: a rotation moves its view as much as this lever arm
 * turned by it */
inline constexpr double kViewLever = 1.5;

/** [m] how far apart two views are: the translation plus the rotation over kViewLever */
inline double viewDistance(const PoseGap& g) { return g.metres + kViewLever * g.radians; }

}  // namespace hrgbd
