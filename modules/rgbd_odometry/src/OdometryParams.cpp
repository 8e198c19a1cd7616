#include "rgbd_odometry/OdometryParams.h"

#include "rgbd_core/Config.h"

namespace hrgbd {

Method parseMethod(const std::string& name) {
  return parseEnum<Method>(name, "Odometry", "method");
}

void OdometryParams::checkTogether(const std::string& s) const {
  requireValid(prediction_max_gap == 0 || prediction_max_gap > 1, s, "prediction_max_gap",
               prediction_max_gap, "must be 0 (always a prediction) or above 1");
}

std::string toString(Method m) { return mrpt::typemeta::TEnumType<Method>::value2name(m); }

}  // namespace hrgbd
