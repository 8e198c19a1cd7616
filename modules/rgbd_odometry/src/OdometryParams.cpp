#include "rgbd_odometry/OdometryParams.h"

#include "rgbd_core/Config.h"

namespace hrgbd {

Method parseMethod(const std::string& name) {
  return parseEnum<Method>(name, "Odometry", "method");
}

std::string toString(Method m) { return mrpt::typemeta::TEnumType<Method>::value2name(m); }

void OdometryParams::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                        const std::string& s) {
  rejectUnknownKeys(c, s,
                    {"method", "min_orb_features", "min_photometric_inliers", "geometric_fallback",
                     "geometric_k_fraction", "max_hamming_distance", "on_failure",
                     "max_step_translation", "max_step_rotation_deg"});
  loadEnum(c, s, "method", method);
  MRPT_LOAD_CONFIG_VAR_CS(min_orb_features, int);
  MRPT_LOAD_CONFIG_VAR_CS(min_photometric_inliers, int);
  MRPT_LOAD_CONFIG_VAR_CS(geometric_fallback, bool);
  MRPT_LOAD_CONFIG_VAR_CS(geometric_k_fraction, double);
  MRPT_LOAD_CONFIG_VAR_CS(max_hamming_distance, int);
  loadEnum(c, s, "on_failure", on_failure);
  MRPT_LOAD_CONFIG_VAR_CS(max_step_translation, double);
  MRPT_LOAD_CONFIG_VAR_CS(max_step_rotation_deg, double);
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
}

void OdometryParams::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                      const std::string& s) const {
  c.write(s, "method", toString(method), mrpt::config::MRPT_SAVE_NAME_PADDING(),
          mrpt::config::MRPT_SAVE_VALUE_PADDING(), enumNames<Method>());
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_orb_features, "[count] fewer ORB features: geometric path");
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_photometric_inliers,
                               "[count] hybrid: fewer photometric inliers: geometric if it works");
  MRPT_SAVE_CONFIG_VAR_COMMENT(geometric_fallback, "hybrid: photometric failure -> geometric");
  MRPT_SAVE_CONFIG_VAR_COMMENT(geometric_k_fraction, "k' of MSSE on SHOT matches");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_hamming_distance, "[bits] ORB match limit");
  c.write(s, "on_failure", mrpt::typemeta::TEnumType<FailurePolicy>::value2name(on_failure),
          mrpt::config::MRPT_SAVE_NAME_PADDING(), mrpt::config::MRPT_SAVE_VALUE_PADDING(),
          enumNames<FailurePolicy>() + ": pose of unregistered frames");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_step_translation, "[m] larger motion per frame: failure");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_step_rotation_deg, "[deg] larger rotation per frame: failure");
  orb.saveToConfigFile(c, "ORB");
  geometric.saveToConfigFile(c, "Geometric");
  msse.saveToConfigFile(c, "MSSE");
}

}  // namespace hrgbd
