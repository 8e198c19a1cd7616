#pragma once
// What the keyframe graph's bookkeeping (KeyframeSlam.cpp) and its loop search (LoopSearch.cpp)
// share: how far apart two views are, and the information of a registration.
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>
#include <cmath>

#include "rgbd_core/PoseGap.h"
#include "rgbd_odometry/RigidFit.h"
#include "rgbd_slam/PoseGraph.h"
#include "rgbd_slam/SlamParams.h"

namespace hrgbd::slam {

inline double angleRad(const mrpt::poses::CPose3D& d) {
  return Eigen::AngleAxisd(toIsometry(d).rotation()).angle();
}

/** [m] typical depth: rotation sigma = translation sigma / lever */
inline constexpr double kLever = kViewLever;

/** [m] how far apart two views are (PoseGap.h) */
inline double viewDistance(const mrpt::poses::CPose3D& d) {
  return hrgbd::viewDistance(PoseGap{d.norm(), angleRad(d)});
}

/** [m] translation sigma of a registration on `inliers` sparse inliers (dense-only: as 10); its
 * rotation's is this over kLever. */
inline double fitSigma(const SlamParams& p, std::size_t inliers, bool loop) {
  return p.edge_sigma * std::sqrt(100.0 / std::max<double>(inliers, 10)) *
         (loop ? p.loop_sigma_factor : 1.0);
}

/** Information of an edge with translation sigma `sigma` (rotation: over kLever). */
inline mrpt::math::CMatrixDouble66 sigmaInformation(double sigma) {
  return edgeInformation(sigma, sigma / kLever);
}

/** Information of a registration on `inliers` sparse inliers (dense-only: as 10). */
inline mrpt::math::CMatrixDouble66 fitInformation(const SlamParams& p, std::size_t inliers,
                                                  bool loop) {
  return sigmaInformation(fitSigma(p, inliers, loop));
}

/** [m] translation sigma of the edge to a keyframe the tracker took after failures, at a
 * predicted pose: 0.5 m and 19 deg, enough to keep the graph connected and for loops to place it.
 */
inline constexpr double kPredictedSigma = 0.5;

}  // namespace hrgbd::slam
