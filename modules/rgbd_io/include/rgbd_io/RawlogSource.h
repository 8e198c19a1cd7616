#pragma once
/** \file RawlogSource.h
 * An MRPT rawlog (gzip or plain; observations-only or SensoryFrame format) as a FrameSource. */
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <deque>
#include <memory>
#include <opencv2/core.hpp>

#include "rgbd_io/FrameSource.h"

namespace hrgbd {

/** Ground truth file expected beside a rawlog: "<dir>/<stem>_groundtruth.txt" (TUM format). */
std::string groundTruthPathFor(const std::string& rawlog_path);

/** Where an output rawlog's (or recording's) ground truth is written: groundTruthPathFor(), or ""
 * when `output` is a device or FIFO, or named in /dev or /proc (/dev/stdout, also when it is
 * redirected to a file), beside which no file goes ("/dev/stdout_groundtruth.txt"). */
std::string groundTruthOutputFor(const std::string& output);

/** Reads CObservation3DRangeScan frames from a rawlog, one at a time. Objects of other types
 * (actions, other observations) are skipped and counted in stats().skipped_objects. Externally
 * stored images are loaded on next() ("<stem>_Images/" or what MRPT detects). Clean end of file
 * -> nullptr; exception naming the file (and entry) for: a file that is no rawlog (garbage, also
 * behind a gzip header), a truncated or corrupt file, a missing external image or image folder,
 * a frame whose time stamp is unset or outside [1970, 1e11 s) (Timestamp.h), a frame whose size
 * differs from the first frame's. */
class RawlogSource : public FrameSource {
 public:
  explicit RawlogSource(const std::string& path);
  mrpt::obs::CObservation3DRangeScan::Ptr next() override;
  Trajectory groundTruth() const override { return m_ground_truth; }
  std::string describe() const override;
  /** Counts the frames in a pass over the file that loads no external image (RawlogCount.cpp);
   * 0 if the file cannot be read to its end (next() then names the problem). */
  std::size_t frameCount(std::size_t at_most = 0) const override;
  /** The rawlog, its external image folder and its ground truth. */
  std::vector<JobPath> inputs() const override;

 private:
  std::string m_path;
  mrpt::io::CFileGZInputStream m_file;
  std::unique_ptr<mrpt::serialization::CArchive> m_archive;
  std::deque<mrpt::obs::CObservation3DRangeScan::Ptr> m_pending;  // from a SensoryFrame
  std::size_t m_entry = 0;
  std::string m_images_dir;
  Trajectory m_ground_truth;
  cv::Size m_first_size;  //!< size of the first frame
  std::size_t m_first_entry = 0;
  std::string m_camera;                 //!< the first frame's sensorLabel
  mrpt::Clock::time_point m_last_time;  //!< the previous frame's time stamp ...
  std::size_t m_last_entry = 0;         //!< ... and its entry

  void checkSize(const mrpt::obs::CObservation3DRangeScan& obs);
};

}  // namespace hrgbd
