#pragma once
/** \file LiveViewer.h
 * MRPT 3D window of the live app: the growing coloured map, the camera path and frustum, the
 * current colour image with the inlier features, and a status text. */
#include <mrpt/gui/CDisplayWindow3D.h>
#include <mrpt/opengl/CFrustum.h>
#include <mrpt/opengl/CPointCloudColoured.h>
#include <mrpt/opengl/CSetOfLines.h>

#include <string>
#include <utility>
#include <vector>

#include "rgbd_map/ColouredMap.h"
#include "rgbd_odometry/RgbdOdometry.h"

namespace hrgbd {

class LiveViewer {
 public:
  /** Opens the window; throws std::runtime_error if there is no X display. */
  explicit LiveViewer(const std::string& title);
  bool isOpen() const { return m_win->isOpen(); }
  /** The key pushed since the last call (lower case), or 0. */
  int key();
  /** Shows a processed frame; `path` are MRPT world poses (opticalToMrptWorld()). */
  void update(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r,
              const ColouredMap& map, const std::vector<mrpt::poses::CPose3D>& path, double fps);
  /** SLAM mode: the map and path moved onto optimised poses; `loops` (indices into `path`) are
   * drawn as red lines and counted in the status line. */
  void snap(const ColouredMap& map, const std::vector<mrpt::poses::CPose3D>& path,
            const std::vector<std::pair<std::size_t, std::size_t>>& loops);
  /** The status line (paused, saved, finished, ...). */
  void status(const std::string& text);
  /** Removes the map and the path (after a reset). */
  void clear();

 private:
  /** Adds the map's points beyond the m_shown already in the cloud (scene locked by the caller). */
  void showNewPoints(const ColouredMap& map);

  mrpt::gui::CDisplayWindow3D::Ptr m_win;
  mrpt::opengl::CPointCloudColoured::Ptr m_cloud;
  mrpt::opengl::CSetOfLines::Ptr m_path;
  mrpt::opengl::CFrustum::Ptr m_frustum;
  mrpt::opengl::CSetOfLines::Ptr m_loops;
  std::size_t m_shown = 0;       // map points already in m_cloud
  std::size_t m_loop_count = 0;  // loops shown (SLAM mode)
};

}  // namespace hrgbd
