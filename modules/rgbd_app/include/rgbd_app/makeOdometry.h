#pragma once
/** \file makeOdometry.h
 * The one place where the apps (playback, live, benchmark) construct their odometry and resolve
 * the SLAM mode. */
#include <mrpt/config/CConfigFileBase.h>

#include <memory>

#include "rgbd_core/JobPaths.h"
#include "rgbd_io/FrameSource.h"
#include "rgbd_odometry/OdometryParams.h"
#include "rgbd_odometry/RgbdOdometry.h"
#include "rgbd_slam/SlamParams.h"

namespace hrgbd {

/** The tracker for `params` ([Odometry], already loaded) with the registration of any method,
 * the baselines' and peers' included; their [RANSAC] and [ICP] parameters are read from `cfg`
 * (strictly: bad values are ConfigErrors). */
std::unique_ptr<RgbdOdometry> makeOdometry(const OdometryParams& params,
                                           const mrpt::config::CConfigFileBase& cfg);

/** `params` with the rolling shutter of the source's camera ([Dense] rolling_shutter_ms), when
 * the source knows it and the INI leaves that key 0. */
OdometryParams withSourceCamera(OdometryParams params, const FrameSource& source);

/** [Slam] from `cfg`, with the command line's --slam (`on`) and --no-slam (`off`) over its
 * `enabled`. Off for a baseline or peer `method`: loops are verified with the product's
 * registration, and those run as published. Throws UsageError for both switches, or for --slam
 * with a baseline or peer. Its `vocabulary` is resolved against `base`, the INI file's folder. */
SlamParams loadSlamParams(const mrpt::config::CConfigFileBase& cfg, const std::string& base,
                          Method method, bool on, bool off);

/** The files the SLAM mode reads (its vocabulary, unless bundled), for checkJobPaths(). */
std::vector<JobPath> slamInputs(const SlamParams& slam);

}  // namespace hrgbd
