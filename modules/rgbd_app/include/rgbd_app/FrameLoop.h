#pragma once
/** \file FrameLoop.h
 * The one loop of the apps: source -> odometry -> sinks. Playback runs it to the end, the live
 * app one step at a time between its window's keys, the benchmark through playback. */
#include <cstddef>
#include <iosfwd>
#include <memory>
#include <vector>

#include "rgbd_app/FrameSink.h"
#include "rgbd_io/FrameSource.h"
#include "rgbd_odometry/RgbdOdometry.h"
#include "rgbd_slam/KeyframeSlam.h"

namespace hrgbd {

class FrameLoop {
 public:
  /** `source` and `sinks` must outlive the loop; sinks get each frame in the order given.
   * `max_frames` > 0 stops the loop after that many frames since the start or the last reset. */
  FrameLoop(FrameSource& source, std::unique_ptr<RgbdOdometry> odometry,
            std::vector<FrameSink*> sinks, std::size_t max_frames = 0);
  /** SLAM mode: every frame also goes through `slam`, whose optimised poses the sinks get before
   * finish() (correct()); with `live_corrections`, also after each optimisation. */
  void setSlam(std::unique_ptr<KeyframeSlam> slam, bool live_corrections = false);
  /** Reads one frame, registers it and hands it to every sink. Returns false, having done
   * nothing, at the end of the data or after max_frames. Source errors propagate. */
  bool step();
  /** step() until it returns false; returns frames(). Does not finish the sinks. */
  std::size_t run();
  /** SLAM mode: completes the loop search, optimises, hands the poses to every sink (correct())
   * and logs what the SLAM mode did, each step a line with its time (timedStep()). Then calls
   * finish(log) on every sink, in order. */
  void finish(std::ostream& log);
  /** Resets the odometry and every sink: the next frame is the new origin. */
  void reset();
  /** [count] frames processed since the start or the last reset. */
  std::size_t frames() const { return m_frames; }
  /** nullptr without SLAM mode. */
  const KeyframeSlam* slam() const { return m_slam.get(); }

 private:
  FrameSource& m_source;
  std::unique_ptr<RgbdOdometry> m_odometry;
  std::unique_ptr<KeyframeSlam> m_slam;
  bool m_live_corrections = false;
  std::vector<FrameSink*> m_sinks;
  std::size_t m_max_frames;
  std::size_t m_frames = 0;
};

}  // namespace hrgbd
