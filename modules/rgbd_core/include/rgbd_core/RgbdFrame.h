#pragma once
/** \file RgbdFrame.h
 * Building and reading CObservation3DRangeScan frames as colour + depth images. */
#include <mrpt/img/TCamera.h>
#include <mrpt/obs/CObservation3DRangeScan.h>

#include <opencv2/core.hpp>
#include <string>

namespace hrgbd {

/** Makes a registered RGB-D observation (depth already registered to colour, as in TUM).
 * \param bgr         8-bit colour image (CV_8UC3, BGR) or empty for none.
 * \param depth_raw   16-bit depth image (CV_16UC1), 0 = no depth.
 * \param depth_unit  [m] per unit of `depth_raw` (1/5000 for TUM). Stored as `rangeUnits`, so the
 *                    raw values keep full precision.
 * \param cam         intrinsics of both cameras (they coincide).
 * \param t           time stamp (Timestamp.h).
 * Throws std::invalid_argument for wrong types, sizes that differ from each other or from `cam`. */
mrpt::obs::CObservation3DRangeScan::Ptr makeRgbdObservation(
    const cv::Mat& bgr, const cv::Mat& depth_raw, double depth_unit, const mrpt::img::TCamera& cam,
    mrpt::Clock::time_point t, const std::string& label = "RGBD");

/** Same with the time stamp in seconds of UNIX time, rounded to MRPT's 100 ns
 * (frameTimeFromSeconds(): std::invalid_argument outside [0, 1e11) s). */
mrpt::obs::CObservation3DRangeScan::Ptr makeRgbdObservation(const cv::Mat& bgr,
                                                            const cv::Mat& depth_raw,
                                                            double depth_unit,
                                                            const mrpt::img::TCamera& cam, double t,
                                                            const std::string& label = "RGBD");

/** Depth of a frame in metres (CV_32FC1, 0 where unknown). Requires `range_is_depth`. */
cv::Mat depthMetres(const mrpt::obs::CObservation3DRangeScan& obs);

/** Colour image as CV_8UC3 BGR (grey images are expanded); empty if the frame has none. */
cv::Mat colourBgr(const mrpt::obs::CObservation3DRangeScan& obs);

/** Time stamp [s, UNIX time] of an observation. */
double timestampSeconds(const mrpt::obs::CObservation& obs);

}  // namespace hrgbd
