#include "rgbd_odometry/OdometryParams.h"

#include "rgbd_core/Config.h"

namespace hrgbd {

Method parseMethod(const std::string& name) {
  if (name == "hybrid") return Method::Hybrid;
  if (name == "rgb_only") return Method::RgbOnly;
  if (name == "depth_only") return Method::DepthOnly;
  if (name == "ransac") return Method::Ransac;
  if (name == "ransac_icp") return Method::RansacIcp;
  if (name == "opencv_rgbd") return Method::OpencvRgbd;
  if (name == "opencv_icp") return Method::OpencvIcp;
  if (name == "opencv_rgbd_icp") return Method::OpencvRgbdIcp;
  throw ConfigError("[Odometry] method = " + name +
                    ": must be hybrid, rgb_only, depth_only, ransac, ransac_icp, opencv_rgbd, "
                    "opencv_icp or opencv_rgbd_icp");
}

const char* toString(Method m) {
  switch (m) {
    case Method::Hybrid:
      return "hybrid";
    case Method::RgbOnly:
      return "rgb_only";
    case Method::DepthOnly:
      return "depth_only";
    case Method::Ransac:
      return "ransac";
    case Method::RansacIcp:
      return "ransac_icp";
    case Method::OpencvRgbd:
      return "opencv_rgbd";
    case Method::OpencvIcp:
      return "opencv_icp";
    case Method::OpencvRgbdIcp:
      return "opencv_rgbd_icp";
  }
  return "?";
}

void OdometryParams::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                        const std::string& s) {
  rejectUnknownKeys(c, s,
                    {"method", "min_orb_features", "min_photometric_inliers", "geometric_fallback",
                     "geometric_k_fraction", "max_hamming_distance", "on_failure",
                     "max_step_translation", "max_step_rotation_deg"});
  MRPT_LOAD_CONFIG_VAR_CS(method, string);
  MRPT_LOAD_CONFIG_VAR_CS(min_orb_features, int);
  MRPT_LOAD_CONFIG_VAR_CS(min_photometric_inliers, int);
  MRPT_LOAD_CONFIG_VAR_CS(geometric_fallback, bool);
  MRPT_LOAD_CONFIG_VAR_CS(geometric_k_fraction, double);
  MRPT_LOAD_CONFIG_VAR_CS(max_hamming_distance, int);
  MRPT_LOAD_CONFIG_VAR_CS(on_failure, string);
  MRPT_LOAD_CONFIG_VAR_CS(max_step_translation, double);
  MRPT_LOAD_CONFIG_VAR_CS(max_step_rotation_deg, double);
  parseMethod(method);
  if (on_failure != "constant_velocity" && on_failure != "hold")
    throw ConfigError("[" + s + "] on_failure = " + on_failure +
                      ": must be constant_velocity or hold");
  requireValid(min_orb_features >= 0, s, "min_orb_features", min_orb_features, "must be >= 0");
  requireValid(min_photometric_inliers >= 0, s, "min_photometric_inliers", min_photometric_inliers,
               "must be >= 0 (0 = off)");
  requireValid(geometric_k_fraction > 0 && geometric_k_fraction <= 1, s, "geometric_k_fraction",
               geometric_k_fraction, "must be in (0, 1]");
  requireValid(max_hamming_distance > 0 && max_hamming_distance <= 256, s, "max_hamming_distance",
               max_hamming_distance, "must be in (0, 256] bits");
  requireValid(max_step_translation > 0, s, "max_step_translation", max_step_translation,
               "must be > 0 m");
  requireValid(max_step_rotation_deg > 0 && max_step_rotation_deg <= 180, s,
               "max_step_rotation_deg", max_step_rotation_deg, "must be in (0, 180] deg");
  orb.loadFromConfigFile(c, "ORB");
  geometric.loadFromConfigFile(c, "Geometric");
  msse.loadFromConfigFile(c, "MSSE");
  ransac.loadFromConfigFile(c, "RANSAC");
  icp.loadFromConfigFile(c, "ICP");
}

void OdometryParams::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                      const std::string& s) const {
  MRPT_SAVE_CONFIG_VAR_COMMENT(method,
                               "hybrid|rgb_only|depth_only|ransac|ransac_icp|opencv_rgbd|"
                               "opencv_icp|opencv_rgbd_icp");
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_orb_features, "[count] fewer ORB features: geometric path");
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_photometric_inliers,
                               "[count] hybrid: fewer photometric inliers: geometric if it works");
  MRPT_SAVE_CONFIG_VAR_COMMENT(geometric_fallback, "hybrid: photometric failure -> geometric");
  MRPT_SAVE_CONFIG_VAR_COMMENT(geometric_k_fraction, "k' of MSSE on SHOT matches");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_hamming_distance, "[bits] ORB match limit");
  MRPT_SAVE_CONFIG_VAR_COMMENT(on_failure, "constant_velocity|hold: pose of unregistered frames");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_step_translation, "[m] larger motion per frame: failure");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_step_rotation_deg, "[deg] larger rotation per frame: failure");
  orb.saveToConfigFile(c, "ORB");
  geometric.saveToConfigFile(c, "Geometric");
  msse.saveToConfigFile(c, "MSSE");
  ransac.saveToConfigFile(c, "RANSAC");
  icp.saveToConfigFile(c, "ICP");
}

}  // namespace hrgbd
