#pragma once
/** \file DepthAgreement.h
 * How well two frames' depths agree after a motion: the plausibility check of an estimate that
 * has nothing else to vouch for it (the dense peers' results, a frame the dense refinement
 * registers alone). Hand-written: neither OpenCV's cv::rgbd odometries nor Open3D's report it. */
#include <Eigen/Geometry>
#include <cstddef>

#include "rgbd_core/RgbdImage.h"

namespace hrgbd {

/** When a warped depth agrees with the reference depth zr there: within
 * relative zr + quadratic zr^2 of it [m]. */
struct DepthTolerance {
  double relative = 0;   //!< [fraction of the depth]
  double quadratic = 0;  //!< [1/m] (a Kinect's noise grows with the square of the depth)
};

/** How many points of the current frame, warped by T into the reference, land on a known
 * reference depth, and how many of them agree with it. */
struct DepthAgreement {
  std::size_t compared = 0;  //!< warped points landing on a known reference depth
  std::size_t agreeing = 0;  //!< of those, within the tolerance
  /** agreeing / compared; 0 when none was compared */
  double share() const { return compared ? double(agreeing) / double(compared) : 0; }
};

/** Every `stride`-th pixel (at least every one) of `cur` in each direction with a depth is moved by
 * T (current -> reference, optical frames, pinhole) and compared with the reference depth at the
 * nearest pixel it lands on. */
DepthAgreement depthAgreement(const RgbdImage& cur, const RgbdImage& ref,
                              const Eigen::Isometry3d& T, const DepthTolerance& tolerance,
                              int stride);

}  // namespace hrgbd
