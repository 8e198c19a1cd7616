#pragma once
/** \file ColouredMap.h
 * The coloured 3D map: registered frames back-projected with their global pose into MRPT's
 * CColouredPointsMap, decimated to one point per voxel so memory is bounded by the volume seen,
 * not by the number of frames. Exports to PLY (MeshLab, CloudCompare) and .3Dscene
 * (SceneViewer3D). Coordinates: the MRPT world of opticalToMrptWorld() (z up). */
#include <mrpt/maps/CColouredPointsMap.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/poses/CPose3D.h>

#include <cstdint>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "rgbd_core/Params.h"

namespace hrgbd {

/** Parameters of ColouredMap. INI section [Map]. */
struct MapParams : public Params<MapParams> {
  double voxel_size = 0.02;  //!< [m] one point per cubic voxel of this side
  int pixel_stride = 2;      //!< [px] every n-th pixel in u and v is inserted
  double min_depth = 0.3;    //!< [m] nearer pixels are not inserted
  double max_depth = 4.0;    //!< [m] farther pixels are not inserted (Kinect noise grows as z^2)

  template <class P, class V>
  static void declare(P& p, V& v) {
    HRGBD_PARAM(voxel_size, "[m] one map point per voxel", Range::atLeast(0.001));
    HRGBD_PARAM(pixel_stride, "[px] every n-th pixel is inserted", Range::atLeast(1));
    HRGBD_PARAM(min_depth, "[m] nearer pixels are not inserted", Range::atLeast(0));
    HRGBD_PARAM(max_depth, "[m] farther pixels are not inserted, > min_depth");
  }
  /** max_depth > min_depth. */
  void checkTogether(const std::string& s) const;
};

class ColouredMap {
 public:
  explicit ColouredMap(const MapParams& params = {});
  /** Inserts a frame seen from `optical_pose` (trajectory pose, optical frame). The first point
   * to fall in a voxel keeps it. Returns the number of points added. Throws
   * std::invalid_argument for a frame without colour or depth (as prepareRgbdImage()). */
  std::size_t insert(const mrpt::obs::CObservation3DRangeScan& obs,
                     const mrpt::poses::CPose3D& optical_pose);
  /** Inserts `local`, a map of frames inserted at the identity pose (one camera's cloud), as
   * seen from `optical_pose`; voxels as above. Returns the number of points added. */
  std::size_t insert(const ColouredMap& local, const mrpt::poses::CPose3D& optical_pose);
  void clear();
  /** Drops the voxel index (over half of a cloud's memory): the map can still be inserted into
   * another, saved and drawn, but no longer inserted into (insert() then throws
   * std::logic_error); clear() makes it a map again. For clouds kept only to be re-inserted. */
  void freeze();
  std::size_t size() const { return m_points.size(); }
  const MapParams& params() const { return m_params; }
  const mrpt::maps::CColouredPointsMap& points() const { return m_points; }
  /** Binary PLY with colour, in full or not at all (OutputFile.h); throws std::runtime_error
   * naming the file on failure. */
  void savePly(const std::string& path) const;

 private:
  /** Adds the point unless its voxel is taken. */
  bool addPoint(double x, double y, double z, float r, float g, float b);

  MapParams m_params;
  std::unordered_set<std::uint64_t> m_voxels;
  mrpt::maps::CColouredPointsMap m_points;
  bool m_frozen = false;  //!< freeze()
};

/** The camera path as a polyline, and a frustum at each of `frustums` evenly spaced poses
 * (MRPT world poses, see opticalToMrptWorld()). */
mrpt::opengl::CSetOfObjects::Ptr trajectoryObject(const std::vector<mrpt::poses::CPose3D>& poses,
                                                  std::size_t frustums = 10);

/** Loop closures as red lines between the camera positions of the pairs of `poses` indices. */
mrpt::opengl::CSetOfObjects::Ptr loopObject(
    const std::vector<mrpt::poses::CPose3D>& poses,
    const std::vector<std::pair<std::size_t, std::size_t>>& loops);

/** Saves map + camera path (+ loop closures) as an MRPT .3Dscene (SceneViewer3D), in full or not
 * at all; throws std::runtime_error naming the file on failure. */
void saveScene(const ColouredMap& map, const std::vector<mrpt::poses::CPose3D>& poses,
               const std::string& path,
               const std::vector<std::pair<std::size_t, std::size_t>>& loops = {});

}  // namespace hrgbd
