#include "rgbd_app/AppConfig.h"

#include <mrpt/config/CConfigFileMemory.h>

#include "PlaybackSection.h"
#include "rgbd_baselines/Baselines.h"
#include "rgbd_core/Config.h"
#include "rgbd_io/TumSource.h"
#include "rgbd_map/ColouredMap.h"
#include "rgbd_odometry/OdometryParams.h"
#include "rgbd_slam/SlamParams.h"

namespace hrgbd {

std::unique_ptr<mrpt::config::CConfigFileBase> loadChecked(const std::string& file) {
  std::unique_ptr<mrpt::config::CConfigFileBase> cfg =
      file.empty() ? std::make_unique<mrpt::config::CConfigFileMemory>() : loadIniFile(file);
  rejectUnknownSections(*cfg);
  return cfg;
}

std::string effectiveConfig(const std::string& config_file) {
  const auto cfg = loadChecked(config_file);
  PlaybackSection pb;
  pb.loadFromConfigFile(*cfg, "Playback");  // the paths are printed as written
  OdometryParams odo;
  odo.loadFromConfigFile(*cfg, "Odometry");
  BaselineParams baselines;
  baselines.loadFromConfigFile(*cfg, BaselineParams::kSection);
  MapParams map;
  map.loadFromConfigFile(*cfg, "Map");
  TumSourceParams tum;
  tum.loadFromConfigFile(*cfg, "TumSource");
  SlamParams slam;
  slam.loadFromConfigFile(*cfg, "Slam");
  mrpt::config::CConfigFileMemory out;
  pb.saveToConfigFile(out, "Playback");
  odo.saveToConfigFile(out, "Odometry");
  baselines.saveToConfigFile(out, BaselineParams::kSection);
  map.saveToConfigFile(out, "Map");
  tum.saveToConfigFile(out, "TumSource");
  slam.saveToConfigFile(out, "Slam");
  return out.getContent();
}

}  // namespace hrgbd
