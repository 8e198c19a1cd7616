#pragma once
/** \file GeometricFeatures.h
 * The geometric path's features (paper III-C to III-F, Algorithm 2 lines 5-10): down-sampled
 * cloud, normals, IS3D points, SHOT descriptors. */
#include "rgbd_core/RgbdImage.h"
#include "rgbd_odometry/GeometricParams.h"
#include "rgbd_odometry/OrbFeatures.h"
#include "rgbd_odometry/PointCloud.h"

namespace hrgbd {

/** Result of extractGeometricFeatures(). */
struct GeometricFeatures {
  FeatureSet features;           //!< IS3D points with SHOT rows (CV_32F); no 2D keypoints
  Points cloud;                  //!< [m] the down-sampled cloud (for the point-to-plane refinement)
  Points normals;                //!< its unit normals (large neighbourhood, III-D)
  std::size_t cloud_points = 0;  //!< back-projected within max_depth
  std::size_t downsampled_points = 0;  //!< after down-sampling
  std::size_t is3d_candidates = 0;     //!< in no dominant orientation, before the cap
  std::size_t dominant_orientations = 0;
  double radius = 0;  //!< [m] down-sampling radius of this frame
  double ms_downsample = 0, ms_normals = 0, ms_is3d = 0, ms_shot = 0;  //!< [ms] per stage
};

/** Runs the geometric stages on one frame. Points are in the colour camera's optical frame. */
GeometricFeatures extractGeometricFeatures(const RgbdImage& image, const GeometricParams& params);

}  // namespace hrgbd
