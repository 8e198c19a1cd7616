#pragma once
/** \file Baselines.h
 * The methods the paper compares against (Tables I-II: ORB + RANSAC, ORB + RANSAC + ICP) and
 * OpenCV contrib's dense odometries as peers, as registrations for the tracker, fed the same
 * prepared frames as the product's own. */
#include <mrpt/config/CLoadableOptions.h>

#include <memory>

#include "rgbd_baselines/IcpRefine.h"
#include "rgbd_baselines/RansacEstimator.h"
#include "rgbd_odometry/OdometryParams.h"
#include "rgbd_odometry/Registration.h"

namespace hrgbd {

/** Parameters of the baselines: INI sections [RANSAC] and [ICP]. */
struct BaselineParams : public mrpt::config::CLoadableOptions {
  RansacParams ransac;
  IcpParams icp;
  /** Loads [RANSAC] and [ICP] (the section argument is not used). */
  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};

/** Registration for any `odometry.method`: the product's (makeRegistration()), ORB + RANSAC,
 * ORB + RANSAC + ICP, or an OpenCV peer. */
std::unique_ptr<Registration> makeAnyRegistration(const OdometryParams& odometry,
                                                  const BaselineParams& baselines);

}  // namespace hrgbd
