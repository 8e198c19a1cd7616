#pragma once
// The playback's optional MRPT outputs (MapSinks.h): the frames with their estimated poses
// (rawlog and simplemap, for RawLogViewer, rawlog-edit and observations2map) and the coloured map.
#include <string>

namespace hrgbd {

/** Output files; "" = not written. */
struct MapOutputPaths {
  std::string output_rawlog, simplemap, map_ply, map_scene;
};

}  // namespace hrgbd
