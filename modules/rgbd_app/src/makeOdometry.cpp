#include "rgbd_app/makeOdometry.h"

#include "rgbd_baselines/Baselines.h"
#include "rgbd_core/Config.h"

namespace hrgbd {

std::unique_ptr<RgbdOdometry> makeOdometry(const OdometryParams& params,
                                           const mrpt::config::CConfigFileBase& cfg) {
  BaselineParams baselines;
  baselines.loadFromConfigFile(cfg, BaselineParams::kSection);
  return std::make_unique<RgbdOdometry>(params, makeAnyRegistration(params, baselines));
}

OdometryParams withSourceCamera(OdometryParams params, const FrameSource& source) {
  if (params.dense.rolling_shutter_ms == 0)
    params.dense.rolling_shutter_ms = source.rollingShutterMs();
  return params;
}

SlamParams loadSlamParams(const mrpt::config::CConfigFileBase& cfg, const std::string& base,
                          Method method, bool on, bool off) {
  if (on && off) throw UsageError("--slam and --no-slam together");
  SlamParams slam;
  slam.loadFromConfigFile(cfg, "Slam");
  if (slam.vocabulary != "bundled") slam.vocabulary = resolvePath(base, slam.vocabulary);
  if (on || off) slam.enabled = on;
  if (slam.enabled && !isProductMethod(method)) {
    if (on)
      throw UsageError(std::string("--slam needs method hybrid, rgb_only or depth_only, not ") +
                       toString(method));
    slam.enabled = false;
  }
  return slam;
}

std::vector<JobPath> slamInputs(const SlamParams& slam) {
  if (!slam.enabled || slam.vocabulary.empty() || slam.vocabulary == "bundled") return {};
  return {{slam.vocabulary, "the vocabulary ([Slam] vocabulary)"}};
}

}  // namespace hrgbd
