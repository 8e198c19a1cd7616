#include "rgbd_live/ViewerSink.h"

namespace hrgbd {

ViewerSink::ViewerSink(LiveViewer& viewer, const ColouredMapSink& map)
    : m_viewer(viewer), m_map(map), m_last(std::chrono::steady_clock::now()) {}

void ViewerSink::add(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r) {
  const auto now = std::chrono::steady_clock::now();
  const double dt = std::chrono::duration<double>(now - m_last).count();
  m_last = now;
  if (dt > 0) m_fps = m_fps == 0 ? 1 / dt : 0.9 * m_fps + 0.1 / dt;
  m_viewer.update(obs, r, m_map.map(), m_map.path(), m_fps);
}

}  // namespace hrgbd
