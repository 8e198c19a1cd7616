#pragma once
// INI section [Playback]: where the default job reads and writes.
#include <string>

#include "MapOutputs.h"
#include "rgbd_core/Params.h"

namespace hrgbd {

// [Playback] section: where the default job reads and writes. load() makes relative paths
// relative to the INI file's folder; loadFromConfigFile() keeps them as written.
struct PlaybackSection : public Params<PlaybackSection> {
  std::string input;                          // rawlog, TUM folder or "openni2"
  std::string trajectory = "trajectory.txt";  // TUM format, optical frame (always written)
  std::string csv;                            // per-frame CSV; "" = none
  MapOutputPaths outputs;                     // keys output_rawlog, simplemap, map_ply, map_scene
  std::string graph;                          // SLAM mode: pose graph, MRPT text; "" = none

  template <class P, class V>
  static void declare(P& p, V& v) {
    HRGBD_PARAM(input, "rawlog, TUM folder or openni2; relative to the INI file");
    HRGBD_PARAM(trajectory, "output trajectory, TUM format (optical frame)");
    HRGBD_PARAM(csv, "per-frame CSV: status, path, counts, ms per stage; empty = none");
    HRGBD_PARAM(graph, "SLAM mode: pose graph in MRPT's text format; empty = none");
    // MapOutputPaths is not a params struct of its own: its fields are this section's keys.
    v(p.outputs.output_rawlog, "output_rawlog", "frames with estimated poses; empty = none");
    v(p.outputs.simplemap, "simplemap", "(pose, frame) pairs for observations2map; empty = none");
    v(p.outputs.map_ply, "map_ply", "coloured map, PLY; empty = none");
    v(p.outputs.map_scene, "map_scene", "coloured map + camera path, .3Dscene; empty = none");
  }

  void load(const mrpt::config::CConfigFileBase& c, const std::string& base) {
    loadFromConfigFile(c, "Playback");
    // The default trajectory (no key) stays relative to the working directory.
    const bool trajectory_given = c.keyExists("Playback", "trajectory");
    for (auto* path : {&input, &trajectory, &csv, &graph, &outputs.output_rawlog,
                       &outputs.simplemap, &outputs.map_ply, &outputs.map_scene})
      if (*path != "openni2" && (path != &trajectory || trajectory_given))
        *path = resolvePath(base, *path);
  }
};

}  // namespace hrgbd
