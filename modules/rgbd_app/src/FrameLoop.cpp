#include "rgbd_app/FrameLoop.h"

#include <ostream>
#include <stdexcept>

#include "rgbd_core/Interrupt.h"
#include "rgbd_core/Progress.h"

namespace hrgbd {

FrameLoop::FrameLoop(FrameSource& source, std::unique_ptr<RgbdOdometry> odometry,
                     std::vector<FrameSink*> sinks, std::size_t max_frames)
    : m_source(source),
      m_odometry(std::move(odometry)),
      m_sinks(std::move(sinks)),
      m_max_frames(max_frames) {
  if (!m_odometry) throw std::invalid_argument("FrameLoop: no odometry");
}

void FrameLoop::setSlam(std::unique_ptr<KeyframeSlam> slam, bool live_corrections) {
  m_slam = std::move(slam);
  m_live_corrections = live_corrections;
}

bool FrameLoop::step() {
  checkInterrupt();  // Ctrl-C, SIGTERM: the run ends here, its outputs not written
  if (m_max_frames > 0 && m_frames >= m_max_frames) return false;
  const auto obs = m_source.next();
  if (!obs) return false;
  auto r = m_odometry->processObservation(*obs);
  const bool corrected = m_slam && m_slam->add(r, *m_odometry);
  for (auto* sink : m_sinks) sink->add(*obs, r);
  if (corrected && m_live_corrections) {
    const auto poses = m_slam->poses();
    for (auto* sink : m_sinks) sink->correct(poses);
  }
  ++m_frames;
  return true;
}

std::size_t FrameLoop::run() {
  while (step()) {
  }
  return m_frames;
}

void FrameLoop::finish(std::ostream& log) {
  checkInterrupt();
  if (m_slam) {
    // each a line with its time: on a long run these take seconds after the last frame
    timedStep(log, "SLAM: last loop searches and final optimisation", [&] { m_slam->flush(); });
    log << toText(m_slam->stats());
    timedStep(log, "SLAM: outputs moved to the optimised poses", [&] {
      const auto poses = m_slam->poses();
      for (auto* sink : m_sinks) sink->correct(poses);
    });
  }
  for (auto* sink : m_sinks) sink->finish(log);
}

void FrameLoop::reset() {
  m_odometry->reset();
  if (m_slam) m_slam->reset();
  for (auto* sink : m_sinks) sink->reset();
  m_frames = 0;
}

}  // namespace hrgbd
