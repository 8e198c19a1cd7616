#include <mrpt/config/CConfigFileBase.h>

#include "rgbd_core/Config.h"
#include "rgbd_sim/Render.h"

namespace hrgbd::sim {

void KinectModel::checkTogether(const std::string& s) const {
  requireValid(max_depth > min_depth, s, "max_depth", max_depth, "must be > min_depth");
  requireValid(edge_dropout + flying_pixels <= 1, s, "flying_pixels", flying_pixels,
               "edge_dropout + flying_pixels must be <= 1");
}

}  // namespace hrgbd::sim
