#pragma once
/** \file ShotDescriptor.h
 * SHOT descriptors (Tombari, Salti, Di Stefano, "Unique signatures of histograms for local
 * surface description", ECCV 2010), used by the paper (III-F) for its IS3D points.
 *
 * Written here because no Debian package provides SHOT without PCL. */
#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "rgbd_odometry/PointCloud.h"

namespace hrgbd {

constexpr int kShotSectors = 32;                       //!< 8 azimuth x 2 elevation x 2 radial
constexpr int kShotBins = 11;                          //!< cosine bins per sector
constexpr int kShotLength = kShotSectors * kShotBins;  //!< 352

/** SHOT's local reference frame at `centre`: eigenvectors of the covariance of the neighbours
 * about the centre, weighted by (radius - distance); x (largest eigenvalue) and z (smallest)
 * point towards the majority of the neighbours, y = z x x. Columns are x, y, z. Returns false
 * with fewer than 3 neighbours. */
bool shotLocalFrame(const Points& points, const std::vector<std::pair<std::size_t, float>>& nbrs,
                    const Eigen::Vector3f& centre, float radius, Eigen::Matrix3f& frame);

/** Result of computeShot(). */
struct ShotResult {
  cv::Mat descriptors;            //!< CV_32F, one unit-norm row of 352 per kept keypoint
  std::vector<std::size_t> kept;  //!< keypoint indices (into `points`) of the rows
};

/** SHOT at each keypoint over the points within `radius`: in the local frame, 32 volumes
 * (8 azimuth, 2 elevation, 2 radial divisions) each hold an 11-bin histogram of the cosine
 * between the neighbour's normal and the frame's z axis; every neighbour is spread over the
 * adjacent cosine bins and volumes (quadrilinear interpolation); the 352 values are normalised
 * to unit length. Keypoints with fewer than `min_neighbours` support points are dropped. */
ShotResult computeShot(const Points& points, const Points& normals, const PointKdTree& tree,
                       const std::vector<std::size_t>& keypoints, double radius,
                       int min_neighbours);

}  // namespace hrgbd
