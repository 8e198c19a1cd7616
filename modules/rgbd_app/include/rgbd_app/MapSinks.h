#pragma once
/** \file MapSinks.h
 * Sinks for MRPT's tools: the coloured map (PLY, .3Dscene), the frames with their estimated
 * poses as a rawlog (RawLogViewer, rawlog-edit) and as a simplemap (observations2map). */
#include <mrpt/maps/CSimpleMap.h>

#include <iosfwd>
#include <memory>
#include <string>
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
  /** `files` are written by finish(); none for a map that is only shown or saved on demand. */
  explicit ColouredMapSink(const MapParams& params, MapFiles files = {});
  /** Registered frames enter the map; every frame extends the path. */
  void add(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r) override;
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

 private:
  ColouredMap m_map;
  MapFiles m_files;
  std::vector<mrpt::poses::CPose3D> m_path;
};

/** Every frame written to a rawlog with its estimated pose (MRPT world) as its sensorPose, where
 * RawLogViewer and `rawlog-edit --list-poses` read it. Colour images go to PNG files. */
class PosedRawlogSink : public FrameSink {
 public:
  /** Starts `path` (RawlogWriter; colour images in imagesFolderFor(path)); throws
   * std::runtime_error if it cannot. */
  explicit PosedRawlogSink(const std::string& path);
  void add(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r) override;
  /** Completes the rawlog and moves it into place (RawlogWriter::close(): throws naming it if a
   * write failed) and logs it. Without finish(), no rawlog appears under its name. */
  void finish(std::ostream& log) override;

 private:
  std::string m_path;
  std::unique_ptr<RawlogWriter> m_writer;
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

 private:
  std::string m_path;
  mrpt::maps::CSimpleMap m_simplemap;
};

}  // namespace hrgbd
