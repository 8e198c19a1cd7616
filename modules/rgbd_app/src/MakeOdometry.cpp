#include "rgbd_app/MakeOdometry.h"

#include "rgbd_baselines/Baselines.h"
#include "rgbd_core/Config.h"

namespace hrgbd {

RgbdOdometry makeOdometry(const OdometryParams& params, const mrpt::config::CConfigFileBase& cfg) {
  BaselineParams baselines;
  loadStrict(baselines, cfg, "RANSAC");
  return RgbdOdometry(params, makeAnyRegistration(params, baselines));
}

}  // namespace hrgbd
