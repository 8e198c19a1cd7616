#pragma once
/** \file FrameSink.h
 * Where processed frames go: trajectory, CSV, map, rawlog, simplemap, progress, viewer. The
 * FrameLoop hands every frame to its sinks in order; what a sink does with it is its own. */
#include <mrpt/obs/CObservation3DRangeScan.h>

#include <iosfwd>

#include "rgbd_odometry/FrameResult.h"
#include "rgbd_slam/SlamPoses.h"

namespace hrgbd {

/** One consumer of the frame loop's output. */
class FrameSink {
 public:
  virtual ~FrameSink() = default;
  /** One processed frame: the observation and what the odometry made of it, in frame order. */
  virtual void add(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r) = 0;
  /** After the last frame: writes what is only complete at the end and says so in `log`. */
  virtual void finish(std::ostream& log) { (void)log; }
  /** The odometry was reset, the next frame is a new origin: sinks that keep poses drop them. */
  virtual void reset() {}
  /** SLAM mode: the poses of every frame added since the start or the last reset were optimised
   * (at the end of a run, before finish(); live, after each optimisation): sinks that keep poses
   * take these instead. */
  virtual void correct(const SlamPoses& slam) { (void)slam; }
};

}  // namespace hrgbd
