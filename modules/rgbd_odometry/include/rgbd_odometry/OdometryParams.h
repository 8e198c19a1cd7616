#pragma once
/** \file OdometryParams.h
 * Parameters of the odometry: INI section [Odometry] and the stage sections it owns. */
#include <mrpt/config/CLoadableOptions.h>

#include <string>

#include "rgbd_odometry/GeometricParams.h"
#include "rgbd_odometry/IcpRefine.h"
#include "rgbd_odometry/MsseEstimator.h"
#include "rgbd_odometry/OrbFeatures.h"
#include "rgbd_odometry/RansacEstimator.h"

namespace hrgbd {

/** Registration methods: the paper's and its baselines (Tables I and II). */
enum class Method {
  Hybrid,     //!< ORB + MSSE; geometric features when too few ORB features (paper)
  RgbOnly,    //!< ORB + MSSE always
  DepthOnly,  //!< geometric (IS3D + SHOT) + MSSE always
  Ransac,     //!< ORB + RANSAC
  RansacIcp,  //!< ORB + RANSAC, refined by ICP on ~15,000 points
  // Peers: OpenCV contrib's dense frame-to-frame odometries, fed the same prepared frames
  OpencvRgbd,     //!< cv::rgbd::RgbdOdometry (photometric, dense)
  OpencvIcp,      //!< cv::rgbd::ICPOdometry (point-to-plane on the depth)
  OpencvRgbdIcp,  //!< cv::rgbd::RgbdICPOdometry (both)
};
/** hybrid|rgb_only|depth_only|ransac|ransac_icp|opencv_rgbd|opencv_icp|opencv_rgbd_icp */
Method parseMethod(const std::string& name);
const char* toString(Method m);

/** What to do with the pose of a frame that cannot be registered. */
enum class FailurePolicy { ConstantVelocity, Hold };

/** Parameters of RgbdOdometry. INI section [Odometry]; the stages read [ORB], [Geometric],
 * [MSSE], [RANSAC] and [ICP]. */
struct OdometryParams : public mrpt::config::CLoadableOptions {
  std::string method = "hybrid";  //!< hybrid|rgb_only|depth_only|ransac|ransac_icp
  int min_orb_features = 50;      //!< [count] fewer ORB features with depth -> geometric path
  /** hybrid only: a photometric registration with fewer inliers is replaced by the geometric
   * path's when that registers (not in the paper; 0 = off). Measured: every good photometric
   * frame had >= 143 inliers, the far plain zig-zag's 9-26. */
  int min_photometric_inliers = 30;
  /** hybrid only: when the photometric path cannot register a frame (too few matches or
   * inliers, ...), try the geometric path before giving up. The paper switches on the feature
   * count alone (false reproduces it). */
  bool geometric_fallback = true;
  /** k' of MSSE on geometric (SHOT) matches, which are mostly outliers (50-80 % measured on the
   * simulated zig-zag and fr3/cabinet), beyond what k_fraction = 0.5 survives. */
  double geometric_k_fraction = 0.2;
  int max_hamming_distance = 64;  //!< [bits] ORB pairs farther apart are never matched
  std::string on_failure = "constant_velocity";  //!< constant_velocity|hold
  double max_step_translation = 0.5;  //!< [m] larger frame-to-frame motion is flagged as failure
  double max_step_rotation_deg = 30;  //!< [deg] larger frame-to-frame rotation is flagged too
  OrbParams orb;
  GeometricParams geometric;
  MsseParams msse;
  RansacParams ransac;
  IcpParams icp;

  /** Loads [Odometry] from `s` and the stage sections [ORB], [Geometric], [MSSE], [RANSAC],
   * [ICP]. */
  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};

}  // namespace hrgbd
