#include "rgbd_core/RgbdImage.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "rgbd_core/RgbdFrame.h"

namespace hrgbd {
namespace {

PinholeCamera toPinhole(const mrpt::img::TCamera& c, const char* which) {
  PinholeCamera p{c.fx(), c.fy(), c.cx(), c.cy(), int(c.ncols), int(c.nrows)};
  for (double v : {p.fx, p.fy, p.cx, p.cy})
    if (!std::isfinite(v))
      throw std::invalid_argument(std::string(which) + " intrinsics are not finite");
  if (!(p.fx > 0 && p.fy > 0))
    throw std::invalid_argument(std::string(which) + " focal length <= 0");
  return p;
}

// Depth seen from the colour camera: each depth pixel -> 3D (depth camera) -> colour pixel.
cv::Mat registerDepth(const cv::Mat& depth, const PinholeCamera& dcam, const PinholeCamera& ccam,
                      const mrpt::poses::CPose3D& colour_wrt_depth, cv::Size colour_size) {
  cv::Mat out(colour_size, CV_32FC1, cv::Scalar(0));
  for (int v = 0; v < depth.rows; ++v)
    for (int u = 0; u < depth.cols; ++u) {
      const float z = depth.at<float>(v, u);
      if (!(z > 0)) continue;
      // MRPT sensor frame: x forward, y left, z up.
      const mrpt::math::TPoint3D p_mrpt(z, -(u - dcam.cx) * z / dcam.fx,
                                        -(v - dcam.cy) * z / dcam.fy);
      const auto p = colour_wrt_depth.inverseComposePoint(p_mrpt);  // colour optical frame
      if (p.z <= 0) continue;
      const int uc = static_cast<int>(std::lround(ccam.fx * p.x / p.z + ccam.cx));
      const int vc = static_cast<int>(std::lround(ccam.fy * p.y / p.z + ccam.cy));
      if (uc < 0 || vc < 0 || uc >= out.cols || vc >= out.rows) continue;
      float& d = out.at<float>(vc, uc);
      if (d == 0 || p.z < d) d = static_cast<float>(p.z);
    }
  return out;
}

// An image must have the size its intrinsics were calibrated for (when they say).
void requireSize(const cv::Mat& img, const mrpt::img::TCamera& c, const char* which) {
  if (c.ncols == 0 || c.nrows == 0) return;
  if (img.cols != static_cast<int>(c.ncols) || img.rows != static_cast<int>(c.nrows))
    throw std::invalid_argument(std::string(which) + " image is " + std::to_string(img.cols) + "x" +
                                std::to_string(img.rows) + " but its intrinsics are for " +
                                std::to_string(c.ncols) + "x" + std::to_string(c.nrows));
}

// Removes the lens distortion of the colour camera (fr1 and fr2 have some) from the grey image
// and the depth registered to it, so that every later stage may assume a pinhole camera. The
// maps are made once per calibration (OpenCV's undistortion maps; depth by nearest neighbour so
// that unknown depth never blends into known depth), in OpenCV's fixed-point form, which remap()
// would make from float maps on every call: the same images, BM_PrepareFrameWithLensDistortion
// 1.41-1.44 -> 1.32-1.36 ms (the undistortion is 1.1 ms of it).
void undistort(RgbdImage& f, const mrpt::img::TCamera& c) {
  if (std::all_of(c.dist.begin(), c.dist.end(), [](double d) { return d == 0; })) return;
  const std::array<double, 11> key{f.cam.fx,
                                   f.cam.fy,
                                   f.cam.cx,
                                   f.cam.cy,
                                   double(f.grey.cols),
                                   double(f.grey.rows),
                                   c.dist[0],
                                   c.dist[1],
                                   c.dist[2],
                                   c.dist[3],
                                   c.dist[4]};
  thread_local std::array<double, 11> made{};
  thread_local cv::Mat linear_xy, linear_a, nearest_xy;
  if (key != made) {
    const cv::Mat K = (cv::Mat_<double>(3, 3) << key[0], 0, key[2], 0, key[1], key[3], 0, 0, 1);
    const cv::Mat D = (cv::Mat_<double>(1, 5) << key[6], key[7], key[8], key[9], key[10]);
    cv::Mat mx, my;
    cv::initUndistortRectifyMap(K, D, cv::noArray(), K, f.grey.size(), CV_32FC1, mx, my);
    cv::convertMaps(mx, my, linear_xy, linear_a, CV_16SC2, false);
    cv::Mat unused;
    cv::convertMaps(mx, my, nearest_xy, unused, CV_16SC2, true);
    made = key;
  }
  cv::remap(f.grey, f.grey, linear_xy, linear_a, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  cv::remap(f.depth, f.depth, nearest_xy, cv::noArray(), cv::INTER_NEAREST, cv::BORDER_CONSTANT, 0);
}

}  // namespace

RgbdImage prepareRgbdImage(const mrpt::obs::CObservation3DRangeScan& obs) {
  if (!obs.hasIntensityImage) throw std::invalid_argument("frame has no colour image");
  if (!obs.hasRangeImage) throw std::invalid_argument("frame has no depth image");
  const cv::Mat bgr = colourBgr(obs);
  if (bgr.empty()) throw std::invalid_argument("frame's colour image is empty or not 8-bit");
  RgbdImage f;
  f.t = timestampSeconds(obs);
  cv::cvtColor(bgr, f.grey, cv::COLOR_BGR2GRAY);
  f.cam = toPinhole(obs.cameraParamsIntensity, "colour camera");
  requireSize(bgr, obs.cameraParamsIntensity, "colour");
  cv::Mat depth = depthMetres(obs);  // throws for range_is_depth = false
  requireSize(depth, obs.cameraParams, "depth");
  cv::patchNaNs(depth, 0);
  cv::threshold(depth, depth, 1e6, 0, cv::THRESH_TOZERO_INV);  // +inf and absurd values -> 0
  if (obs.doDepthAndIntensityCamerasCoincide() && depth.size() == f.grey.size()) {
    f.depth = depth;
  } else {
    f.depth = registerDepth(depth, toPinhole(obs.cameraParams, "depth camera"), f.cam,
                            obs.relativePoseIntensityWRTDepth, f.grey.size());
  }
  undistort(f, obs.cameraParamsIntensity);
  return f;
}

}  // namespace hrgbd
