#include "rgbd_app/FrameLoop.h"

#include <stdexcept>

namespace hrgbd {

FrameLoop::FrameLoop(FrameSource& source, std::unique_ptr<RgbdOdometry> odometry,
                     std::vector<FrameSink*> sinks, std::size_t max_frames)
    : m_source(source),
      m_odometry(std::move(odometry)),
      m_sinks(std::move(sinks)),
      m_max_frames(max_frames) {
  if (!m_odometry) throw std::invalid_argument("FrameLoop: no odometry");
}

bool FrameLoop::step() {
  if (m_max_frames > 0 && m_frames >= m_max_frames) return false;
  const auto obs = m_source.next();
  if (!obs) return false;
  const auto r = m_odometry->processObservation(*obs);
  for (auto* sink : m_sinks) sink->add(*obs, r);
  ++m_frames;
  return true;
}

std::size_t FrameLoop::run() {
  while (step()) {
  }
  return m_frames;
}

void FrameLoop::finish(std::ostream& log) {
  for (auto* sink : m_sinks) sink->finish(log);
}

void FrameLoop::reset() {
  m_odometry->reset();
  for (auto* sink : m_sinks) sink->reset();
  m_frames = 0;
}

}  // namespace hrgbd
