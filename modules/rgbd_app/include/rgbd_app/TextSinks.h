#pragma once
/** \file TextSinks.h
 * Sinks that write text as the frames come: the TUM trajectory, the per-frame CSV and the
 * progress bar. Files are flushed line by line, so a run that stops keeps what it wrote. */
#include <fstream>
#include <iosfwd>
#include <string>

#include "rgbd_app/FrameSink.h"
#include "rgbd_core/Trajectory.h"

namespace hrgbd {

/** The estimated trajectory, kept in memory and, when given a file, written to it as TUM lines
 * (writeTumLine()) after a first '#' comment line. */
class TrajectorySink : public FrameSink {
 public:
  /** Memory only (trajectory()). */
  TrajectorySink() = default;
  /** Also writes `path`, starting with `comment` (a line starting with '#'); throws
   * std::runtime_error if the file cannot be written. */
  TrajectorySink(const std::string& path, const std::string& comment);
  void add(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r) override;
  /** Logs "trajectory: <path>" when writing a file. */
  void finish(std::ostream& log) override;
  /** Drops the poses kept in memory; lines already written stay in the file. */
  void reset() override { m_trajectory.clear(); }
  /** Poses (optical frame of the first camera) since the start or the last reset. */
  const Trajectory& trajectory() const { return m_trajectory; }

 private:
  std::string m_path;
  std::ofstream m_file;
  Trajectory m_trajectory;
};

/** One CSV row per frame with the FrameResult's figures (status, path, counts, stage times). */
class CsvSink : public FrameSink {
 public:
  /** Writes the header; throws std::runtime_error if `path` cannot be written. */
  explicit CsvSink(const std::string& path);
  void add(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r) override;

 private:
  std::ofstream m_file;
};

/** A one-line progress bar (frames, registered, time of the last frame) redrawn per frame. */
class ProgressSink : public FrameSink {
 public:
  /** Draws on `out` (a terminal: the line is redrawn with '\r'). */
  explicit ProgressSink(std::ostream& out) : m_out(out) {}
  void add(const mrpt::obs::CObservation3DRangeScan& obs, const FrameResult& r) override;
  /** Ends the bar's line on its own stream; `log` is not used. */
  void finish(std::ostream& log) override;

 private:
  std::ostream& m_out;
  std::size_t m_frames = 0, m_registered = 0;
};

}  // namespace hrgbd
