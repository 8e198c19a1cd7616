#include "rgbd_app/AppConfig.h"

#include <mrpt/config/CConfigFileMemory.h>

#include <algorithm>

#include "PlaybackSection.h"
#include "rgbd_baselines/Baselines.h"
#include "rgbd_core/Config.h"
#include "rgbd_io/TumSource.h"
#include "rgbd_map/ColouredMap.h"
#include "rgbd_odometry/OdometryParams.h"

namespace hrgbd {

const std::vector<std::string>& knownConfigSections() {
  static const std::vector<std::string> s{"Playback", "Odometry",  "ORB", "Geometric",
                                          "MSSE",     "RANSAC",    "ICP", "TumSource",
                                          "OpenNI2",  "Benchmark", "Map"};
  return s;
}

void rejectUnknownSections(const mrpt::config::CConfigFileBase& cfg) {
  std::vector<std::string> sections;
  cfg.getAllSections(sections);
  const auto& known = knownConfigSections();
  for (const auto& s : sections)
    if (!s.empty() && std::find(known.begin(), known.end(), s) == known.end())
      throw ConfigError("unknown INI section [" + s + "]");
}

std::unique_ptr<mrpt::config::CConfigFileBase> loadChecked(const std::string& file) {
  std::unique_ptr<mrpt::config::CConfigFileBase> cfg =
      file.empty() ? std::make_unique<mrpt::config::CConfigFileMemory>() : loadIniFile(file);
  rejectUnknownSections(*cfg);
  return cfg;
}

std::string effectiveConfig(const std::string& config_file) {
  const auto cfg = loadChecked(config_file);
  PlaybackSection pb;
  pb.load(*cfg, ".");  // rejects unknown [Playback] keys; the paths are printed as written
  OdometryParams odo;
  loadStrict(odo, *cfg, "Odometry");
  TumSourceParams tum;
  loadStrict(tum, *cfg, "TumSource");
  mrpt::config::CConfigFileMemory out;
  for (const auto& key :
       {"input", "trajectory", "csv", "output_rawlog", "simplemap", "map_ply", "map_scene"})
    out.write("Playback", key, cfg->read_string("Playback", key, ""));
  odo.saveToConfigFile(out, "Odometry");
  BaselineParams baselines;
  loadStrict(baselines, *cfg, "RANSAC");
  baselines.saveToConfigFile(out, "RANSAC");
  MapParams map;
  loadStrict(map, *cfg, "Map");
  map.saveToConfigFile(out, "Map");
  tum.saveToConfigFile(out, "TumSource");
  return out.getContent();
}

}  // namespace hrgbd
