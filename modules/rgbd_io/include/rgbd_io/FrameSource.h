#pragma once
/** \file FrameSource.h
 * The one seam between data (rawlog, TUM folder, live sensor, simulator) and the odometry. */
#include <mrpt/obs/CObservation3DRangeScan.h>

#include <cstddef>
#include <string>
#include <vector>

#include "rgbd_core/JobPaths.h"
#include "rgbd_core/Trajectory.h"

namespace hrgbd {

/** Counters of what a source has read so far. */
struct SourceStats {
  std::size_t frames = 0;           //!< 3D range-scan frames returned
  std::size_t skipped_objects = 0;  //!< objects of other types passed over (counted, not lost)
};

/** A stream of RGB-D frames.
 * next() returns the next frame, or nullptr at the end of the data, and only then. Any error
 * (unreadable file, corrupt or truncated data, missing image, a time stamp outside
 * Timestamp.h's range) throws std::runtime_error whose message names the file and the entry. */
class FrameSource {
 public:
  virtual ~FrameSource() = default;
  virtual mrpt::obs::CObservation3DRangeScan::Ptr next() = 0;
  /** Ground truth of the colour camera (optical frame, TUM convention); empty if none. */
  virtual Trajectory groundTruth() const { return {}; }
  /** One line saying what this source reads, for logs. */
  virtual std::string describe() const = 0;
  /** The files and folders it reads, which no output may overwrite (checkJobPaths()); none for a
   * sensor. */
  virtual std::vector<JobPath> inputs() const { return {}; }
  /** [count] Frames next() gives in all, when known or countable before the run (progress),
   * or `at_most` if there are more (0 = no limit); 0 = unknown (a live sensor). May read the
   * input once, up to `at_most` frames; never throws (0 instead). */
  virtual std::size_t frameCount(std::size_t at_most = 0) const {
    (void)at_most;
    return 0;
  }
  /** [ms] The camera's rolling-shutter readout, first row to last, when the source knows the
   * camera; 0 = unknown or a global shutter. */
  virtual double rollingShutterMs() const { return 0; }
  const SourceStats& stats() const { return m_stats; }

 protected:
  SourceStats m_stats;
};

}  // namespace hrgbd
