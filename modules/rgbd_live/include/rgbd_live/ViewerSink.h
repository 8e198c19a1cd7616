#pragma once
/** \file ViewerSink.h
 * The live window as a frame sink: each frame with the map, the camera path and the frame rate. */
#include <chrono>

#include "rgbd_app/FrameSink.h"
#include "rgbd_app/MapSinks.h"
#include "rgbd_live/LiveViewer.h"

namespace hrgbd {

class ViewerSink : public FrameSink {
 public:
  /** Shows the map and path of `map`, which must come before this sink in the loop (so the
   * frame shown is in the map shown). Both must outlive the sink. */
  ViewerSink(LiveViewer& viewer, const ColouredMapSink& map);
  /** Updates the window; the frame rate is smoothed over the frames shown. */
  void add(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r) override;
  /** Removes the map and the path from the window. */
  void reset() override { m_viewer.clear(); }
  /** SLAM mode: shows the map and path the map sink (before this one) moved, and the loops. */
  void correct(const SlamPoses& slam) override {
    m_viewer.snap(m_map.map(), m_map.path(), slam.loops);
  }

 private:
  LiveViewer& m_viewer;
  const ColouredMapSink& m_map;
  std::chrono::steady_clock::time_point m_last;
  double m_fps = 0;  // [Hz]
};

}  // namespace hrgbd
