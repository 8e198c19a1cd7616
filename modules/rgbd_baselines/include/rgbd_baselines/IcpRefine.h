#pragma once
/** \file IcpRefine.h
 * ICP refinement of the ORB+RANSAC+ICP baseline (paper section IV-C), using MRPT's CICP. */
#include <Eigen/Geometry>

#include "rgbd_core/Params.h"
#include "rgbd_core/RgbdImage.h"
#include "rgbd_odometry/RigidFit.h"

namespace hrgbd {

/** Parameters of refineIcp(). INI section [ICP]. */
struct IcpParams : public Params<IcpParams> {
  int target_points = 15000;  //!< [count] clouds down-sampled to about this many (paper: 15,000)
  int max_iterations = 40;    //!< ICP iterations
  double max_distance = 0.1;  //!< [m] initial pairing distance (MRPT thresholdDist)
  double max_depth = 5.0;     //!< [m] points farther are not used

  template <class P, class V>
  static void declare(P& p, V& v) {
    HRGBD_PARAM(target_points, "[count] points per cloud after down-sampling", Range::atLeast(100));
    HRGBD_PARAM(max_iterations, "ICP iterations", Range::atLeast(1));
    HRGBD_PARAM(max_distance, "[m] initial pairing distance", Range::above(0));
    HRGBD_PARAM(max_depth, "[m] farther points unused", Range::above(0));
  }
};

struct IcpResult {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();  //!< source -> target after ICP
  unsigned iterations = 0;
  double goodness = 0;  //!< MRPT's ratio of paired points, [0, 1]
};

/** Refines `initial` (source -> target) by point-to-point ICP between the two depth clouds. */
IcpResult refineIcp(const RgbdImage& source, const RgbdImage& target,
                    const Eigen::Isometry3d& initial, const IcpParams& params);

}  // namespace hrgbd
