#pragma once
/** \file PointCloud.h
 * Geometric path pre-processing (paper III-C, III-D): the cropped, down-sampled cloud of a
 * depth image and its surface normals, plus the KD-tree (nanoflann) both use. */
#include <Eigen/Core>
#include <memory>
#include <utility>
#include <vector>

#include "rgbd_core/RgbdImage.h"
#include "rgbd_odometry/GeometricParams.h"

namespace hrgbd {

using Points = std::vector<Eigen::Vector3f>;

/** Result of downsampleDepth(). */
struct DownsampledCloud {
  Points points;                 //!< [m] optical frame, one centroid per occupied cell
  double radius = 0;             //!< [m] cell size used (chosen per frame)
  double mean_spacing = 0;       //!< [m] mean nearest-neighbour distance of the input cloud
  std::size_t input_points = 0;  //!< back-projected points within max_depth
};

/** Back-projects every `pixel_stride`-th depth pixel (eqs. 1-2), drops points beyond
 * `max_depth`, and replaces all points of each cubic cell of edge `radius` by their centroid.
 * The radius is chosen per frame: first from the mean nearest-neighbour spacing s of the input
 * (measured between grid neighbours) as s sqrt(N / target_points), then corrected up to three
 * times by the ratio of cells obtained to `target_points` (cells scale as 1/radius^2 on
 * surfaces), so about `target_points` remain. Empty depth gives an empty cloud. */
DownsampledCloud downsampleDepth(const RgbdImage& image, const GeometricParams& params);

/** Fixed-radius neighbour search over a point set (nanoflann KD-tree). */
class PointKdTree {
 public:
  explicit PointKdTree(const Points& points);
  ~PointKdTree();
  PointKdTree(const PointKdTree&) = delete;
  PointKdTree& operator=(const PointKdTree&) = delete;
  /** Indices and squared distances of the points within `radius` [m] of `query` (itself too). */
  void radiusSearch(const Eigen::Vector3f& query, float radius,
                    std::vector<std::pair<std::size_t, float>>& out) const;
  /** Nearest point to `query`: its index and squared distance; false for an empty set. */
  bool nearest(const Eigen::Vector3f& query, std::size_t& index, float& dist2) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

/** Unit normal of each point from a least-squares plane through its neighbours within `radius`
 * (smallest eigenvector of their covariance), oriented towards the camera at the origin
 * (paper III-D). Points with fewer than 3 neighbours get the direction to the camera. */
Points estimateNormals(const Points& points, const PointKdTree& tree, double radius);

}  // namespace hrgbd
