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

}  // namespace hrgbd
