#pragma once
/** \file PlaneIcp.h
 * Point-to-plane ICP between two down-sampled clouds, refining the geometric path's MSSE
 * estimate (an addition to the paper: see GeometricParams::refine_iterations).
 *
 * Written here because MRPT 2.5's CICP has no point-to-plane variant for 3D clouds, and
 * mp2p_icp is not packaged for Debian 12. */
#include <Eigen/Geometry>

#include "rgbd_odometry/PointCloud.h"

namespace hrgbd {

/** Result of refinePointToPlane(). */
struct PlaneIcpResult {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();  //!< source -> target
  int iterations = 0;
  std::size_t pairs = 0;  //!< source points paired in the last iteration
  double rms = 0;         //!< [m] RMS point-to-plane distance of the pairs
  bool converged = false;
};

/** Minimises sum_i w_i (n_i . (T p_i - q_i))^2 over source points p_i paired with their nearest
 * target point q_i (normal n_i) within `max_distance` [m]; Gauss-Newton on a small-angle
 * linearisation, Huber weights w_i at 1.345 robust sigmas, and a small damping so directions
 * the scene does not constrain (e.g. sliding along a single plane) stay at `initial`. Stops
 * after `iterations` or when the update is below 0.1 mm and 0.01 deg. */
PlaneIcpResult refinePointToPlane(const Points& source, const Points& target,
                                  const Points& target_normals, const PointKdTree& target_tree,
                                  const Eigen::Isometry3d& initial, int iterations,
                                  double max_distance);

}  // namespace hrgbd
