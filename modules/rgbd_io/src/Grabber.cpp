#include "rgbd_io/Grabber.h"

#include <chrono>

#include "rgbd_core/RgbdFrame.h"

namespace hrgbd {

Grabber::Grabber(std::unique_ptr<FrameSource> source, bool drop, double rate)
    : m_source(std::move(source)),
      m_description(m_source->describe()),
      m_ground_truth(m_source->groundTruth()),
      m_drop(drop),
      m_rate(rate),
      m_thread([this] { run(); }) {}

Grabber::~Grabber() {
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_stop = true;
  }
  m_changed.notify_all();
  m_thread.join();
}

void Grabber::run() {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  double t0 = -1;
  try {
    while (auto obs = m_source->next()) {
      if (m_rate > 0) {
        const double t = timestampSeconds(*obs);
        if (t0 < 0) t0 = t;
        std::this_thread::sleep_until(start +
                                      std::chrono::duration_cast<Clock::duration>(
                                          std::chrono::duration<double>((t - t0) / m_rate)));
      }
      std::unique_lock<std::mutex> lock(m_mutex);
      if (m_drop && m_queue.size() >= 2) {
        m_queue.pop_front();
        ++m_dropped;
      }
      m_changed.wait(lock, [&] { return m_stop || m_queue.size() < 2; });
      if (m_stop) return;
      m_queue.push_back(obs);
      m_skipped = m_source->stats().skipped_objects;
      m_changed.notify_all();
    }
  } catch (...) {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_error = std::current_exception();
  }
  std::lock_guard<std::mutex> lock(m_mutex);
  m_skipped = m_source->stats().skipped_objects;
  m_ended = true;
  m_changed.notify_all();
}

mrpt::obs::CObservation3DRangeScan::Ptr Grabber::next() {
  std::unique_lock<std::mutex> lock(m_mutex);
  m_changed.wait(lock, [&] { return !m_queue.empty() || m_ended; });
  m_stats.skipped_objects = m_skipped;
  if (m_queue.empty()) {
    if (m_error) std::rethrow_exception(m_error);
    return nullptr;
  }
  auto obs = m_queue.front();
  m_queue.pop_front();
  ++m_stats.frames;
  m_changed.notify_all();
  return obs;
}

std::size_t Grabber::dropped() const {
  std::lock_guard<std::mutex> lock(m_mutex);
  return m_dropped;
}

}  // namespace hrgbd
