#pragma once
/** \file makeOdometry.h
 * The one place where the apps (playback, live, benchmark) construct their odometry. */
#include <memory>

#include "rgbd_odometry/OdometryParams.h"
#include "rgbd_odometry/RgbdOdometry.h"

namespace hrgbd {

/** The odometry for `params` ([Odometry] section). Throws ConfigError for a method that is
 * unknown or not available in this build. */
std::unique_ptr<RgbdOdometry> makeOdometry(const OdometryParams& params);

}  // namespace hrgbd
