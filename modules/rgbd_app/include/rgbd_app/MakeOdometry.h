#pragma once
/** \file MakeOdometry.h
 * The one place where the apps build the tracker with the registration of any method. */
#include <mrpt/config/CConfigFileBase.h>

#include "rgbd_odometry/RgbdOdometry.h"

namespace hrgbd {

/** The tracker for `params` (already loaded from [Odometry]); a baseline's [RANSAC] and [ICP]
 * parameters are read from `cfg` (strictly: bad values are ConfigErrors). */
RgbdOdometry makeOdometry(const OdometryParams& params, const mrpt::config::CConfigFileBase& cfg);

}  // namespace hrgbd
