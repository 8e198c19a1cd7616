#pragma once
/** \file Grabber.h
 * A FrameSource that reads another one on its own thread, ahead of the odometry, as a sensor
 * driver would. */
#include <condition_variable>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "rgbd_io/FrameSource.h"

namespace hrgbd {

/** Reads frames on its own thread into a queue of two. A live source (sensor) never waits:
 * when the consumer is behind, the oldest queued frame is dropped (and counted). A recorded
 * source waits for the consumer (no frame lost) and, with `rate` > 0, is paced at `rate` times
 * its recorded time stamps; `rate` = 0 reads as fast as the consumer takes them. */
class Grabber : public FrameSource {
 public:
  Grabber(std::unique_ptr<FrameSource> source, bool live, double rate);
  ~Grabber() override;
  /** The next queued frame (waits for one), nullptr at the end of the data. Rethrows the
   * source's error. */
  mrpt::obs::CObservation3DRangeScan::Ptr next() override;
  /** The wrapped source's description. Its ground truth and statistics are not forwarded: the
   * wrapped source is read on the grabber's thread. */
  std::string describe() const override { return m_description; }
  /** [count] frames dropped because the consumer was behind a live source. */
  std::size_t dropped() const;

 private:
  void run();
  std::unique_ptr<FrameSource> m_source;
  std::string m_description;
  bool m_live;
  double m_rate;
  mutable std::mutex m_mutex;
  std::condition_variable m_changed;
  std::deque<mrpt::obs::CObservation3DRangeScan::Ptr> m_queue;
  bool m_ended = false, m_stop = false;
  std::exception_ptr m_error;
  std::size_t m_dropped = 0;
  std::thread m_thread;  // last: starts after the members it uses
};

}  // namespace hrgbd
