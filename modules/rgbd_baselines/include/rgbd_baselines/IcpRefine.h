#pragma once
/** \file IcpRefine.h
 * ICP refinement of the ORB+RANSAC+ICP baseline (paper section IV-C), using MRPT's CICP. */
#include <mrpt/config/CLoadableOptions.h>

#include <Eigen/Geometry>

#include "rgbd_core/RgbdImage.h"
#include "rgbd_odometry/RigidFit.h"

namespace hrgbd {

/** Parameters of refineIcp(). INI section [ICP]. */
struct IcpParams : public mrpt::config::CLoadableOptions {
  int target_points = 15000;  //!< [count] clouds down-sampled to about this many (paper: 15,000)
  int max_iterations = 40;    //!< ICP iterations
  double max_distance = 0.1;  //!< [m] initial pairing distance (MRPT thresholdDist)
  double max_depth = 5.0;     //!< [m] points farther are not used

  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
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
