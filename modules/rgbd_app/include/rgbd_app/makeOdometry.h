#pragma once
/** \file makeOdometry.h
 * The one place where the apps (playback, live, benchmark) construct their odometry. */
#include <mrpt/config/CConfigFileBase.h>

#include <memory>

#include "rgbd_odometry/OdometryParams.h"
#include "rgbd_odometry/RgbdOdometry.h"

namespace hrgbd {

/** The tracker for `params` ([Odometry], already loaded) with the registration of any method,
 * the baselines' and peers' included; their [RANSAC] and [ICP] parameters are read from `cfg`
 * (strictly: bad values are ConfigErrors). */
std::unique_ptr<RgbdOdometry> makeOdometry(const OdometryParams& params,
                                           const mrpt::config::CConfigFileBase& cfg);

}  // namespace hrgbd
