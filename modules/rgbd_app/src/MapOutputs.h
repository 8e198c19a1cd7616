#pragma once
// The playback's optional MRPT outputs: the frames with their estimated poses (rawlog and
// simplemap, for RawLogViewer, rawlog-edit and observations2map) and the coloured map.
#include <mrpt/maps/CSimpleMap.h>

#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rgbd_io/RawlogWriter.h"
#include "rgbd_map/ColouredMap.h"
#include "rgbd_odometry/RgbdOdometry.h"

namespace hrgbd {

struct MapOutputPaths {
  std::string output_rawlog, simplemap, map_ply, map_scene;
};

class MapOutputs {
 public:
  MapOutputs(const MapOutputPaths& paths, const MapParams& params);
  /** One processed frame. Only registered frames enter the map; every frame is written. */
  void add(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r);
  /** Writes the files that are only complete at the end; returns the map size. */
  std::size_t finish(std::ostream& log);

 private:
  MapOutputPaths m_paths;
  std::unique_ptr<RawlogWriter> m_rawlog;
  mrpt::maps::CSimpleMap m_simplemap;
  std::optional<ColouredMap> m_map;
  std::vector<mrpt::poses::CPose3D> m_path;  // MRPT world poses of the camera
};

}  // namespace hrgbd
