#pragma once
/** \file Grabber.h
 * A FrameSource that reads another one on its own thread, ahead of the odometry, as a sensor
 * driver would: the live sensor's path, and a recording played as if it were one. */
#include <condition_variable>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "rgbd_io/FrameSource.h"

namespace hrgbd {

/** Reads frames on its own thread into a queue of two.
 * - `drop` (a live sensor, or a recording played as one): the grabber never waits for the
 *   consumer; a frame that arrives while the queue is full pushes out the oldest queued frame,
 *   which is dropped and counted. The consumer always gets the oldest frame not yet dropped.
 * - otherwise the grabber waits for the consumer: no frame is lost.
 * With `rate` > 0 the frames are delivered on their time stamps, at `rate` times the recorded
 * speed (give 0 for a sensor, which delivers at its own pace); `rate` = 0 reads as fast as the
 * source gives them. Nothing is read before the consumer's first next(), whose time is the first
 * frame's: the consumer's own setup drops nothing. `max_frames` > 0 reads at most that many
 * frames of the source (delivered or dropped). */
class Grabber : public FrameSource {
 public:
  Grabber(std::unique_ptr<FrameSource> source, bool drop, double rate, std::size_t max_frames = 0);
  ~Grabber() override;
  /** Stops reading (the consumer is done): dropped() no longer changes; next() then gives what
   * is queued, then nullptr. */
  void stop();
  /** The next queued frame (waits for one), nullptr at the end of the data. Rethrows the
   * source's error. */
  mrpt::obs::CObservation3DRangeScan::Ptr next() override;
  /** The wrapped source's description and ground truth, taken before its thread started; its
   * skipped objects are counted in stats() as they are queued. */
  std::string describe() const override { return m_description; }
  Trajectory groundTruth() const override { return m_ground_truth; }
  /** [count] frames dropped because the consumer was behind (only with `drop`). */
  std::size_t dropped() const;

 private:
  void run();
  std::unique_ptr<FrameSource> m_source;
  std::string m_description;
  Trajectory m_ground_truth;
  bool m_drop;
  double m_rate;
  std::size_t m_max_frames;
  mutable std::mutex m_mutex;
  std::condition_variable m_changed;
  std::deque<mrpt::obs::CObservation3DRangeScan::Ptr> m_queue;
  bool m_ended = false, m_stop = false;
  bool m_asked = false;  //!< the consumer called next(): the clock runs
  std::exception_ptr m_error;
  std::size_t m_dropped = 0;
  std::size_t m_skipped = 0;  //!< the source's skipped objects, read on the grabber's thread
  std::thread m_thread;       // last: starts after the members it uses
};

}  // namespace hrgbd
