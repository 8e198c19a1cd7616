#include "rgbd_odometry/OdometryParams.h"

#include "rgbd_core/Config.h"

namespace hrgbd {

Method parseMethod(const std::string& name) {
  return parseEnum<Method>(name, "Odometry", "method");
}

std::string toString(Method m) { return mrpt::typemeta::TEnumType<Method>::value2name(m); }

}  // namespace hrgbd
