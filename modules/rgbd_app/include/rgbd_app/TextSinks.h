#pragma once
/** \file TextSinks.h
 * Sinks that write text as the frames come: the TUM trajectory, the per-frame CSV and the
 * progress line. The files are OutputFiles (rgbd_core/OutputFile.h): each line is written and
 * flushed, with the write checked, to a temporary file beside the output, which finish() moves
 * into place; a run that fails leaves no partial trajectory or CSV under the output's name. */
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "rgbd_app/FrameSink.h"
#include "rgbd_core/OutputFile.h"
#include "rgbd_core/Progress.h"
#include "rgbd_core/Trajectory.h"
#include "rgbd_io/FrameSource.h"

namespace hrgbd {

/** The estimated trajectory, kept in memory and, when given a file, written to it as TUM lines
 * (writeTumLine()) after a first '#' comment line. Each pose has its frame's time stamp
 * (obs.timestamp), written exactly (formatFrameTime()). */
class TrajectorySink : public FrameSink {
 public:
  /** Memory only (trajectory(), save()). */
  TrajectorySink() = default;
  /** Also writes `path`, starting with `comment` (a line starting with '#'); throws
   * std::runtime_error if the file cannot be written. With `streamed`, each pose is written as
   * its frame comes (a FIFO or /dev/stdout follows the run); without it (the SLAM mode, whose
   * poses correct() replaces), finish() writes every pose once: an output that is a device or
   * FIFO cannot be rewritten, and got the odometry's poses and then the optimised ones. */
  TrajectorySink(const std::string& path, const std::string& comment, bool streamed = true);
  /** Throws std::runtime_error naming the file when the line cannot be written. */
  void add(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r) override;
  /** Writes the poses not yet written, moves the file into place (throws naming it if a write
   * failed) and logs "trajectory: <path> ... <time>" (timedStep()). */
  void finish(std::ostream& log) override;
  /** Drops the poses kept in memory; lines already written stay in the file. */
  void reset() override;
  /** Takes the optimised poses, which finish() writes; throws std::logic_error on a streamed
   * sink whose lines are already written. */
  void correct(const SlamPoses& slam) override;
  /** Poses (optical frame of the first camera) since the start or the last reset. */
  const Trajectory& trajectory() const { return m_trajectory; }
  /** Writes the poses kept in memory to `path` (TUM, exact time stamps), in full or not at all;
   * throws naming the file on failure. */
  void save(const std::string& path, const std::string& comment) const;

 private:
  std::unique_ptr<StreamOutput> m_file;
  bool m_streamed = true;
  bool m_corrected = false;
  Trajectory m_trajectory;
  std::vector<std::string> m_times;  //!< formatFrameTime() of each pose in m_trajectory
};

/** One CSV row per frame with the FrameResult's figures (status, path, counts, stage times); the
 * timestamp column is the frame's exact time stamp. */
class CsvSink : public FrameSink {
 public:
  /** Writes the header; throws std::runtime_error if `path` cannot be written. */
  explicit CsvSink(const std::string& path);
  /** Throws std::runtime_error naming the file when the row cannot be written. */
  void add(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r) override;
  /** Moves the file into place (throws naming it if a write failed) and logs "CSV: <path> ...
   * <time>" (timedStep()). */
  void finish(std::ostream& log) override;

 private:
  StreamOutput m_file;
};

/** The run's progress (rgbd_core/Progress.h): frames done of the total when known, frames per
 * second, time left and frames not registered; redrawn in place on a terminal, a line now and
 * then otherwise. */
class ProgressSink : public FrameSink {
 public:
  /** Writes to `out`; `clock` as Progress's (tests inject one). */
  ProgressSink(std::ostream& out, const ProgressParams& params, Progress::Clock clock = {})
      : m_progress(out, params, std::move(clock)) {}
  void add(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r) override;
  /** Writes the final line on its own stream; `log` is not used. Once: later calls do nothing
   * (the playback ends the line before the final steps, FrameLoop::finish() calls it again). */
  void finish(std::ostream& log) override;

 private:
  Progress m_progress;
  std::size_t m_frames = 0, m_registered = 0;
};

/** ProgressParams of a run over `source`: its frame count (FrameSource::frameCount(), at most
 * `max_frames` when > 0), `label`, and whether stderr is a terminal. */
ProgressParams frameProgress(const FrameSource& source, std::size_t max_frames,
                             const std::string& label);

}  // namespace hrgbd
