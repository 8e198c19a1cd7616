#pragma once
/** \file RgbdImage.h
 * A frame prepared for registration: grey image, depth registered to it, pinhole intrinsics. */
#include <mrpt/obs/CObservation3DRangeScan.h>

#include <opencv2/core.hpp>

#include "rgbd_core/PinholeCamera.h"

namespace hrgbd {

/** Grey image (CV_8UC1), depth in metres registered to it (CV_32FC1, 0 = unknown), camera. */
struct RgbdImage {
  cv::Mat grey;
  cv::Mat depth;
  PinholeCamera cam;
  double t = 0;  //!< [s]
};

/** Prepares an observation. If depth and colour cameras do not coincide, the depth is
 * re-projected into the colour camera using `relativePoseIntensityWRTDepth` (nearest depth wins).
 * Throws std::invalid_argument naming what is wrong: no colour image, no depth, ranges instead of
 * depths, non-positive or non-finite intrinsics. Non-finite depth values become 0 (unknown).
 * Lens distortion of the colour camera is removed from both images (pinhole from here on). */
RgbdImage prepareRgbdImage(const mrpt::obs::CObservation3DRangeScan& obs);

}  // namespace hrgbd
