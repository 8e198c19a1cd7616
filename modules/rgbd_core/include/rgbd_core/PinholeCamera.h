#pragma once
/** \file PinholeCamera.h
 * The project's one camera type: pinhole intrinsics of the colour camera [px] and the image size.
 * MRPT's TCamera (with distortion) stays at the observation boundary; prepareRgbdImage() converts
 * it, and the simulator renders with this type. */
#include <Eigen/Core>

namespace hrgbd {

struct PinholeCamera {
  double fx = 525, fy = 525, cx = 319.5, cy = 239.5;  //!< [px]
  int width = 640, height = 480;                      //!< [px]
  /** Paper eqs. (1)-(2): pixel (u, v) at depth z [m] -> point in the optical frame [m]. */
  Eigen::Vector3d backProject(double u, double v, double z) const {
    return {(u - cx) * z / fx, (v - cy) * z / fy, z};
  }
};

}  // namespace hrgbd
