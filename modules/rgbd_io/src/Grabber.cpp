#include "rgbd_io/Grabber.h"

#include <chrono>

#include "rgbd_core/RgbdFrame.h"

namespace hrgbd {

Grabber::Grabber(std::unique_ptr<FrameSource> source, bool drop, double rate,
                 std::size_t max_frames)
    : m_source(std::move(source)),
      m_description(m_source->describe()),
      m_ground_truth(m_source->groundTruth()),
      m_drop(drop),
      m_rate(rate),
      m_max_frames(max_frames),
      m_thread([this] { run(); }) {}

Grabber::~Grabber() { stop(); }

void Grabber::stop() {
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_stop = true;
  }
  m_changed.notify_all();
  if (m_thread.joinable()) m_thread.join();
}

void Grabber::run() {
  using Clock = std::chrono::steady_clock;
  try {
    // the clock starts when the consumer first asks: its own setup drops nothing
    {
      std::unique_lock<std::mutex> lock(m_mutex);
      m_changed.wait(lock, [&] { return m_stop || m_asked; });
      if (m_stop) return;
    }
    const auto start = Clock::now();
    double t0 = -1;
    std::size_t read = 0;
    while (m_max_frames == 0 || read < m_max_frames) {
      auto obs = m_source->next();
      if (!obs) break;
      ++read;
      std::unique_lock<std::mutex> lock(m_mutex);
      if (m_rate > 0) {  // on its time stamp; a stop ends the wait
        const double t = timestampSeconds(*obs);
        if (t0 < 0) t0 = t;
        const auto due = start + std::chrono::duration_cast<Clock::duration>(
                                     std::chrono::duration<double>((t - t0) / m_rate));
        m_changed.wait_until(lock, due, [&] { return m_stop; });
      }
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
  if (!m_asked) {
    m_asked = true;
    m_changed.notify_all();
  }
  m_changed.wait(lock, [&] { return !m_queue.empty() || m_ended || m_stop; });
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
