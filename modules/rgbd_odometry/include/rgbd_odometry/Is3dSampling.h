#pragma once
/** \file Is3dSampling.h
 * Informatively sampled 3D features, IS3D (paper III-E, Algorithm 1): keep the points whose
 * normal belongs to no dominant normal orientation (edges, corners, curved surfaces). */
#include <Eigen/Core>
#include <vector>

#include "rgbd_odometry/GeometricParams.h"
#include "rgbd_odometry/PointCloud.h"

namespace hrgbd {

/** One dominant normal orientation found by Algorithm 1. */
struct DominantOrientation {
  Eigen::Vector3f normal;  //!< the winning reference normal
  std::size_t points = 0;  //!< group size after the MSSE growth
  double sigma_deg = 0;    //!< [deg] MSSE scale of the group's angle residuals (eq. 5)
};

/** Result of sampleIs3d(). */
struct Is3dResult {
  std::vector<std::size_t> indices;  //!< IS3D points (ascending), at most is3d_points
  std::size_t candidates = 0;        //!< points in no dominant group, before the cap
  std::vector<DominantOrientation> groups;
};

/** Algorithm 1, applied repeatedly. For up to `is3d_references` random reference points the
 * angle residuals phi = arccos(n_ref . n_j) (eq. 3) to the remaining points are squared and the
 * k'-th smallest is taken, k' = is3d_k_fraction * (all points); the reference with the least one
 * gives a dominant orientation, and the MSSE constraint (eqs. 4-5, T = is3d_T, model dimension
 * p = 2) grows its group from k'. The group is removed and the search repeats on the rest, until
 * fewer than k' points remain, the best k'-th order angle exceeds is3d_max_group_angle_deg, or
 * is3d_max_groups groups were removed. The points left belong to no dominant orientation; when
 * more than is3d_points, a random subset is kept. Deterministic for a given seed.
 *
 * Where the paper reads its third group off the same residual curve (Fig. 4), this removes each
 * dominant group and searches again, so any number of plane orientations (not only two) is
 * separated. A single plane leaves almost no point. */
Is3dResult sampleIs3d(const Points& normals, const GeometricParams& params);

}  // namespace hrgbd
