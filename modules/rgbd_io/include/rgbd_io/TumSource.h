#pragma once
/** \file TumSource.h
 * A TUM RGB-D dataset folder (rgb.txt, depth.txt, optional groundtruth.txt) as a FrameSource. */
#include <mrpt/img/TCamera.h>

#include <algorithm>
#include <opencv2/core.hpp>
#include <vector>

#include "rgbd_core/Params.h"
#include "rgbd_io/FrameSource.h"
#include "rgbd_io/TumLists.h"

namespace hrgbd {

/** Parameters of TumSource. INI section [TumSource]. */
struct TumSourceParams : public Params<TumSourceParams> {
  double max_time_difference = 0.02;  //!< [s] colour/depth pairs further apart are not associated
  double depth_factor = 5000.0;       //!< [units per metre] depth PNG value / factor = metres
  /** auto (the folder's calibration.txt, "fx fy cx cy" as in ETH3D's RGB-D folders and as
   * rgbd-simulate --tum writes it; without one, guessed from the folder's path, else ros_default
   * with a warning on stderr), fr1, fr2, fr3,
   * ros_default (presets for 640x480, scaled to other sizes of that aspect ratio), or explicit
   * (fx, fy, cx, cy below, in pixels of the folder's images, any size). */
  std::string intrinsics = "auto";
  double fx = 525.0, fy = 525.0;  //!< [px] focal lengths, only with intrinsics = explicit
  double cx = 319.5, cy = 239.5;  //!< [px] principal point, only with intrinsics = explicit
  /** [ms] rolling-shutter readout of the fr1 and fr2 Kinects, first row to last: the frames of a
   * folder whose camera is fr1 or fr2 get it as [Dense] rolling_shutter_ms unless that is set
   * (0 = not undone). Not fr3: on its slow sequences the correction measured no consistent gain
   * (doc/measurements.md). */
  double rolling_shutter_ms = 30;

  template <class P, class V>
  static void declare(P& p, V& v) {
    HRGBD_PARAM(max_time_difference, "[s] max colour/depth time difference", Range::open(0, 1));
    HRGBD_PARAM(depth_factor, "[units/m] depth PNG value / factor = metres", Range::above(0));
    HRGBD_PARAM(intrinsics, "camera of the folder",
                OneOf{{"auto", "fr1", "fr2", "fr3", "ros_default", "explicit"}});
    HRGBD_PARAM(fx, "[px] only with intrinsics = explicit", Range::above(0));
    HRGBD_PARAM(fy, "[px] only with intrinsics = explicit", Range::above(0));
    HRGBD_PARAM(cx, "[px] only with intrinsics = explicit");
    HRGBD_PARAM(cy, "[px] only with intrinsics = explicit");
    HRGBD_PARAM(rolling_shutter_ms, "[ms] readout of the fr1 and fr2 cameras (0 = not undone)",
                Range::atLeast(0));
  }
};

class TumSource : public FrameSource {
 public:
  /** Reads and associates the lists, and the calibration.txt it uses (a malformed one, or a
   * broken link, is refused); throws naming the file if anything is wrong. Frames carry
   * their list time stamps exactly (Timestamp.h). Image names in the lists are relative to the
   * folder, or absolute. next() throws naming the image for: a missing or undecodable image, a
   * depth image that is not single-channel 16-bit, colour and depth of different sizes, a size
   * other than the first frame's, a size the preset intrinsics cannot be scaled to (another
   * aspect ratio), explicit intrinsics (INI or calibration.txt) with a principal point off the
   * image or a focal length outside 1/20 to 20 times its size, and an image declaring more than
   * 4096 x 4096 pixels. */
  TumSource(const std::string& folder, const TumSourceParams& params = {});
  mrpt::obs::CObservation3DRangeScan::Ptr next() override;
  Trajectory groundTruth() const override { return m_ground_truth; }
  std::string describe() const override;
  /** The lists, groundtruth.txt, calibration.txt, association lists (associat*.txt) and every
   * listed image, present or not. */
  std::vector<JobPath> inputs() const override { return m_inputs; }

  const mrpt::img::TCamera& camera() const { return m_camera; }
  std::size_t size() const { return m_pairs.size(); }
  std::size_t frameCount(std::size_t at_most = 0) const override {
    return at_most > 0 ? std::min(at_most, size()) : size();
  }
  std::size_t unmatchedColour() const { return m_unmatched_rgb; }
  /** rolling_shutter_ms for the fr1 and fr2 cameras, 0 for others. */
  double rollingShutterMs() const override;

 private:
  std::string m_folder;
  TumSourceParams m_params;
  mrpt::img::TCamera m_camera;
  std::string m_camera_name;
  std::string m_camera_origin;       //!< where the intrinsics come from, for describe()
  std::string m_intrinsics_warning;  //!< printed once, when the first frame is read
  cv::Size m_first_size;             //!< size of the first frame read
  std::string m_first_file;          //!< its colour image
  std::vector<TumPair> m_pairs;
  std::size_t m_next = 0, m_unmatched_rgb = 0;
  Trajectory m_ground_truth;
  std::vector<JobPath> m_inputs;

  std::string imagePath(const std::string& file) const;
  mrpt::img::TCamera cameraFor(cv::Size size, const std::string& file) const;
  /** For the first frame (`size`, colour image `file`): throws for a principal point off the
   * image or a focal length outside 1/20 to 20 times the image size; warns once for a principal
   * point over a sixth of the image off its centre. */
  void checkExplicitCamera(const mrpt::img::TCamera& cam, cv::Size size,
                           const std::string& file) const;
};

}  // namespace hrgbd
