#pragma once
/** \file OrbFeatures.h
 * Photometric features (paper section III-B): ORB keypoints back-projected with the depth. */
#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "rgbd_core/Params.h"
#include "rgbd_core/RgbdImage.h"

namespace hrgbd {

/** Parameters of extractOrbFeatures(). INI section [ORB]. */
struct OrbParams : public Params<OrbParams> {
  int n_features = 1000;      //!< [count] most keypoints kept by OpenCV's ORB
  double scale_factor = 1.2;  //!< pyramid decimation ratio (> 1)
  int n_levels = 8;           //!< pyramid levels
  int fast_threshold = 20;    //!< FAST intensity threshold [grey levels]
  double min_depth = 0.3;     //!< [m] keypoints nearer than this are dropped
  double max_depth = 5.0;     //!< [m] keypoints farther than this are dropped (paper III-C)

  template <class P, class V>
  static void declare(P& p, V& v) {
    HRGBD_PARAM(n_features, "[count] most ORB keypoints per frame", Range::closed(10, 100000));
    HRGBD_PARAM(scale_factor, "pyramid decimation ratio", Range::openClosed(1, 2));
    HRGBD_PARAM(n_levels, "pyramid levels", Range::closed(1, 16));
    HRGBD_PARAM(fast_threshold, "[grey levels] FAST threshold", Range::closed(1, 255));
    HRGBD_PARAM(min_depth, "[m] keypoints nearer are dropped", Range::atLeast(0));
    HRGBD_PARAM(max_depth, "[m] keypoints farther are dropped (paper III-C), > min_depth");
  }
  /** max_depth > min_depth. */
  void checkTogether(const std::string& s) const;
};

/** Keypoints with valid depth, their descriptors (one row each) and 3D points. */
struct FeatureSet {
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;                  //!< CV_8U rows (ORB) or CV_32F rows (SHOT)
  std::vector<Eigen::Vector3d> points;  //!< [m] optical frame of the colour camera
  std::size_t detected = 0;             //!< keypoints found before the depth check
  std::size_t dropped_no_depth = 0;     //!< keypoints without valid depth (dropped, counted)
  std::size_t size() const { return points.size(); }
};

/** ORB on `image.grey`; each keypoint gets the depth of its pixel and is back-projected with
 * equations (1)-(2). Keypoints without depth in [min_depth, max_depth] are dropped. */
FeatureSet extractOrbFeatures(const RgbdImage& image, const OrbParams& params);

}  // namespace hrgbd
