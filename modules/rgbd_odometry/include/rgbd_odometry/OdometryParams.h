#pragma once
/** \file OdometryParams.h
 * Parameters of the odometry: INI section [Odometry] and the stage sections it owns. */
#include <mrpt/config/CLoadableOptions.h>

#include <string>

#include "rgbd_odometry/GeometricParams.h"
#include "rgbd_odometry/MsseEstimator.h"
#include "rgbd_odometry/OrbFeatures.h"

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
/** The method named `name` (INI and command-line spelling, e.g. "rgb_only"); throws ConfigError
 * listing the names otherwise. */
Method parseMethod(const std::string& name);
std::string toString(Method m);

/** What to do with the pose of a frame that cannot be registered. */
enum class FailurePolicy {
  ConstantVelocity,  //!< the last registered motion is repeated
  Hold,              //!< the pose stays where it was
};

/** Parameters of RgbdOdometry. INI section [Odometry]; the stages read [ORB], [Geometric] and
 * [MSSE]. The baselines' [RANSAC] and [ICP] are BaselineParams (rgbd_baselines). */
struct OdometryParams : public mrpt::config::CLoadableOptions {
  Method method = Method::Hybrid;
  int min_orb_features = 50;  //!< [count] fewer ORB features with depth -> geometric path
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
  FailurePolicy on_failure = FailurePolicy::ConstantVelocity;  //!< pose of unregistered frames
  double max_step_translation = 0.5;  //!< [m] larger frame-to-frame motion is flagged as failure
  double max_step_rotation_deg = 30;  //!< [deg] larger frame-to-frame rotation is flagged too
  OrbParams orb;
  GeometricParams geometric;
  MsseParams msse;

  /** Loads [Odometry] from `s` and the stage sections [ORB], [Geometric], [MSSE]. */
  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};

}  // namespace hrgbd

MRPT_ENUM_TYPE_BEGIN(hrgbd::Method)
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::Method::Hybrid, "hybrid");
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::Method::RgbOnly, "rgb_only");
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::Method::DepthOnly, "depth_only");
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::Method::Ransac, "ransac");
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::Method::RansacIcp, "ransac_icp");
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::Method::OpencvRgbd, "opencv_rgbd");
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::Method::OpencvIcp, "opencv_icp");
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::Method::OpencvRgbdIcp, "opencv_rgbd_icp");
MRPT_ENUM_TYPE_END()

MRPT_ENUM_TYPE_BEGIN(hrgbd::FailurePolicy)
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::FailurePolicy::ConstantVelocity, "constant_velocity");
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::FailurePolicy::Hold, "hold");
MRPT_ENUM_TYPE_END()
