#pragma once
/** \file MapSinks.h
 * Sinks for MRPT's tools: the coloured map (PLY, .3Dscene), the frames with their estimated
 * poses as a rawlog (RawLogViewer, rawlog-edit) and as a simplemap (observations2map). */
#include <mrpt/maps/CSimpleMap.h>

#include <iosfwd>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "rgbd_app/FrameSink.h"
#include "rgbd_io/RawlogWriter.h"
#include "rgbd_map/ColouredMap.h"

namespace hrgbd {

/** Files of a coloured map; "" = not written. */
struct MapFiles {
  std::string ply;    //!< binary PLY with colour
  std::string scene;  //!< map + camera path as an MRPT .3Dscene
};

/** The coloured map of the registered frames and the camera path (every frame). */
class ColouredMapSink : public FrameSink {
 public:
  /** `files` are written by finish(); none for a map that is only shown or saved on demand.
   * `keyframes_only` (SLAM mode): only the pose graph's nodes (FrameResult::node) enter the map,
   * each kept as its own cloud so that correct() rebuilds the map at the optimised poses; a node
   * whose view is within `cloud_spacing` [m] (PoseGap.h's viewDistance) of a kept cloud's adds
   * nothing: the map's memory follows the views of the scene, not the time spent in them. */
  explicit ColouredMapSink(const MapParams& params, MapFiles files = {},
                           bool keyframes_only = false, double cloud_spacing = 0);
  /** Registered frames (nodes only, see above) enter the map; every frame extends the
   * path. */
  void add(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r) override;
  /** Moves the path onto the optimised poses, rebuilds the map from the keyframes' clouds (with
   * `keyframes_only`) and keeps the loops, which the .3Dscene draws. */
  void correct(const SlamPoses& slam) override;
  /** Writes the files given at construction and logs each. */
  void finish(std::ostream& log) override;
  /** Empties the map and the path. */
  void reset() override;
  /** Writes the map as it is now to `files`, each in full or not at all (OutputFile.h); throws
   * std::runtime_error naming the file on failure. */
  void save(const MapFiles& files) const;
  const ColouredMap& map() const { return m_map; }
  /** Camera poses in the MRPT world (opticalToMrptWorld()). */
  const std::vector<mrpt::poses::CPose3D>& path() const { return m_path; }
  /** Loop edges (frame indices) of the latest correct(). */
  const std::vector<std::pair<std::size_t, std::size_t>>& loops() const { return m_loops; }

 private:
  ColouredMap m_map;
  MapFiles m_files;
  bool m_keyframes_only;
  double m_cloud_spacing;
  std::vector<mrpt::poses::CPose3D> m_path;
  std::vector<std::pair<std::size_t, ColouredMap>> m_clouds;  //!< (frame, cloud in its camera)
  std::vector<std::pair<std::size_t, std::size_t>> m_loops;
};

/** Every frame written to a rawlog with its estimated pose (MRPT world) as its sensorPose, where
 * RawLogViewer and `rawlog-edit --list-poses` read it. Colour images go to PNG files. */
class PosedRawlogSink : public FrameSink {
 public:
  /** Starts `path` (RawlogWriter; colour images in imagesFolderFor(path)); throws
   * std::runtime_error if it cannot. */
  explicit PosedRawlogSink(const std::string& path);
  void add(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r) override;
  /** Keeps the optimised poses: finish() writes them as the frames' sensorPose. */
  void correct(const SlamPoses& slam) override;
  /** Completes the rawlog and moves it into place (RawlogWriter::close(): throws naming it if a
   * write failed) and logs it. Without finish(), no rawlog appears under its name. After
   * correct(), the rawlog is then rewritten with the optimised poses (read back object by
   * object, so memory stays bounded; the external images are not touched). */
  void finish(std::ostream& log) override;

 private:
  std::string m_path;
  std::unique_ptr<RawlogWriter> m_writer;
  std::vector<mrpt::poses::CPose3D> m_corrected;
};

/** Every frame, with its point cloud and inline colour image, at its estimated pose (MRPT
 * world) in a CSimpleMap, as observations2map reads it. */
class SimplemapSink : public FrameSink {
 public:
  explicit SimplemapSink(const std::string& path) : m_path(path) {}
  void add(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r) override;
  /** Writes the file in full or not at all (throws std::runtime_error naming it if it cannot)
   * and logs it. */
  void finish(std::ostream& log) override;
  void reset() override { m_simplemap.clear(); }
  /** Moves every (pose, frame) pair onto its optimised pose. */
  void correct(const SlamPoses& slam) override;

 private:
  std::string m_path;
  mrpt::maps::CSimpleMap m_simplemap;
};

}  // namespace hrgbd
