#pragma once
// INI section [Playback]: where the default job reads and writes.
#include <mrpt/config/CConfigFileBase.h>

#include <string>

#include "MapOutputs.h"
#include "rgbd_core/Config.h"

namespace hrgbd {

// [Playback] section: where the default job reads and writes. Relative paths are relative to
// the INI file's folder.
struct PlaybackSection {
  std::string input, trajectory = "trajectory.txt", csv;
  MapOutputPaths outputs;
  void load(const mrpt::config::CConfigFileBase& c, const std::string& base) {
    rejectUnknownKeys(
        c, "Playback",
        {"input", "trajectory", "csv", "output_rawlog", "simplemap", "map_ply", "map_scene"});
    auto path = [&](const std::string& key, const std::string& def) {
      const auto v = c.read_string("Playback", key, def);
      return v == "openni2" ? v : resolvePath(base, v);
    };
    input = path("input", "");
    trajectory = c.keyExists("Playback", "trajectory") ? path("trajectory", "") : trajectory;
    csv = path("csv", "");
    outputs = {path("output_rawlog", ""), path("simplemap", ""), path("map_ply", ""),
               path("map_scene", "")};
  }
};

}  // namespace hrgbd
