#include "rgbd_app/makeOdometry.h"

namespace hrgbd {

std::unique_ptr<RgbdOdometry> makeOdometry(const OdometryParams& params) {
  return std::make_unique<RgbdOdometry>(params);
}

}  // namespace hrgbd
