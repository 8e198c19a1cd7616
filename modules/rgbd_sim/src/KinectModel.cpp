#include <mrpt/config/CConfigFileBase.h>

#include "rgbd_core/Config.h"
#include "rgbd_sim/Render.h"

namespace hrgbd::sim {

const std::vector<std::string>& KinectModel::keys() {
  static const std::vector<std::string> k{"baseline",           "disparity_step",
                                          "disparity_noise",    "disparity_noise_correlated",
                                          "correlation_window", "disparity_distortion",
                                          "edge_fattening",     "min_depth",
                                          "max_depth",          "min_incidence",
                                          "edge_dropout",       "flying_pixels",
                                          "colour_noise",       "exposure_ms",
                                          "rolling_shutter_ms", "auto_exposure"};
  return k;
}

void KinectModel::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) {
  MRPT_LOAD_CONFIG_VAR_CS(baseline, double);
  MRPT_LOAD_CONFIG_VAR_CS(disparity_step, double);
  MRPT_LOAD_CONFIG_VAR_CS(disparity_noise, double);
  MRPT_LOAD_CONFIG_VAR_CS(disparity_noise_correlated, double);
  MRPT_LOAD_CONFIG_VAR_CS(correlation_window, int);
  MRPT_LOAD_CONFIG_VAR_CS(disparity_distortion, double);
  MRPT_LOAD_CONFIG_VAR_CS(edge_fattening, int);
  MRPT_LOAD_CONFIG_VAR_CS(min_depth, double);
  MRPT_LOAD_CONFIG_VAR_CS(max_depth, double);
  MRPT_LOAD_CONFIG_VAR_CS(min_incidence, double);
  MRPT_LOAD_CONFIG_VAR_CS(edge_dropout, double);
  MRPT_LOAD_CONFIG_VAR_CS(flying_pixels, double);
  MRPT_LOAD_CONFIG_VAR_CS(colour_noise, double);
  MRPT_LOAD_CONFIG_VAR_CS(exposure_ms, double);
  MRPT_LOAD_CONFIG_VAR_CS(rolling_shutter_ms, double);
  MRPT_LOAD_CONFIG_VAR_CS(auto_exposure, double);
  requireValid(baseline > 0 && baseline < 1, s, "baseline", baseline, "must be in (0, 1) m");
  requireValid(disparity_step >= 0 && disparity_step <= 1, s, "disparity_step", disparity_step,
               "must be in [0, 1] px (0 = not quantised)");
  for (const auto& [key, v] : {std::pair{"disparity_noise", disparity_noise},
                               {"disparity_noise_correlated", disparity_noise_correlated},
                               {"disparity_distortion", disparity_distortion}})
    requireValid(v >= 0 && v <= 5, s, key, v, "must be in [0, 5] px");
  requireValid(correlation_window >= 1 && correlation_window <= 31, s, "correlation_window",
               correlation_window, "must be in [1, 31] px");
  requireValid(edge_fattening >= 0 && edge_fattening <= 15, s, "edge_fattening", edge_fattening,
               "must be in [0, 15] px");
  requireValid(min_depth > 0 && max_depth > min_depth, s, "max_depth", max_depth,
               "must be > min_depth > 0");
  requireValid(min_incidence >= 0 && min_incidence < 1, s, "min_incidence", min_incidence,
               "must be in [0, 1)");
  requireValid(edge_dropout >= 0 && flying_pixels >= 0 && edge_dropout + flying_pixels <= 1, s,
               "edge_dropout", edge_dropout, "and flying_pixels must be >= 0 with a sum <= 1");
  requireValid(colour_noise >= 0 && colour_noise <= 50, s, "colour_noise", colour_noise,
               "must be in [0, 50] grey levels");
  requireValid(exposure_ms >= 0 && exposure_ms <= 100, s, "exposure_ms", exposure_ms,
               "must be in [0, 100] ms");
  requireValid(rolling_shutter_ms >= 0 && rolling_shutter_ms <= 100, s, "rolling_shutter_ms",
               rolling_shutter_ms, "must be in [0, 100] ms");
  requireValid(auto_exposure >= 0 && auto_exposure < 1, s, "auto_exposure", auto_exposure,
               "must be in [0, 1)");
}

void KinectModel::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const {
  MRPT_SAVE_CONFIG_VAR_COMMENT(baseline, "[m] projector-camera baseline");
  MRPT_SAVE_CONFIG_VAR_COMMENT(disparity_step, "[px] disparity quantisation");
  MRPT_SAVE_CONFIG_VAR_COMMENT(disparity_noise, "[px] per-pixel disparity noise (std)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(disparity_noise_correlated, "[px] smooth noise field (std)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(correlation_window, "[px] block-matching window (1 = none)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(disparity_distortion, "[px] fixed-pattern disparity error (std)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(edge_fattening, "[px] foreground depth spreads this far");
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_depth, "[m] no depth nearer");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_depth, "[m] no depth farther");
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_incidence, "|cos| of grazing incidence without depth");
  MRPT_SAVE_CONFIG_VAR_COMMENT(edge_dropout, "probability of no depth at a discontinuity");
  MRPT_SAVE_CONFIG_VAR_COMMENT(flying_pixels, "probability of a mixed depth at a discontinuity");
  MRPT_SAVE_CONFIG_VAR_COMMENT(colour_noise, "[grey levels] colour noise (std)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(exposure_ms, "[ms] exposure (motion blur)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(rolling_shutter_ms, "[ms] readout, first to last row (0 = global)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(auto_exposure, "relative amplitude of slow gain changes");
}

}  // namespace hrgbd::sim
