#pragma once
/** \file RigidFit.h
 * Closed-form weighted rigid fit (paper eqs. 6-7) and the random 3-point hypotheses shared by the
 * MSSE and RANSAC estimators.
 *
 * Written here because mrpt::tfest::se3_l2 (Horn's method) takes no per-point weights, which
 * equation (6) needs; with unit weights the two agree (tested). */
#include <mrpt/poses/CPose3D.h>

#include <Eigen/Geometry>
#include <cstdint>
#include <functional>
#include <vector>

namespace hrgbd {

/** Corresponding 3D points: source[i] (current frame) <-> target[i] (previous frame), [m]. */
struct Correspondences {
  std::vector<Eigen::Vector3d> source, target;
  std::size_t size() const { return source.size(); }
};

/** T* = argmin_T sum_i w_i |T(p_s,i) - p_t,i|^2 over the rows `idx` (all if empty): weighted
 * centroids, weighted cross-covariance, SVD with the reflection fix (Kabsch/Umeyama, no scale). */
Eigen::Isometry3d fitRigidWeighted(const Correspondences& c, const std::vector<double>& w,
                                   const std::vector<std::size_t>& idx = {});

/** Weights of eq. (6), decreasing with depth: 1 / (z_s^2 + z_t^2), normalised to mean 1 (all
 * ones when `enabled` is false). A keypoint's lateral error grows as z and its depth error as
 * z^2; on fr3/teddy 1/z^4 weights (pure depth-noise model) gave a worse trajectory than 1/z^2
 * (aligned ATE 0.125 m vs 0.050 m), as they leave the far points that fix rotation unused. */
std::vector<double> depthWeights(const Correspondences& c, bool enabled);

/** True when three points cannot fix a rotation: two (nearly) coincide or all are (nearly)
 * collinear, i.e. the triangle's smallest height is below `min_spread` [m]. */
bool isDegenerateTriple(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                        const Eigen::Vector3d& c, double min_spread);

/** Draws `count` random 3-tuples of distinct rows (std::mt19937 seeded with `seed`), skips
 * degenerate ones in source or target (counted in the return value), fits each with
 * fitRigidWeighted() and calls `visit(T)`. Returns the number of degenerate samples. */
std::size_t forEachHypothesis(const Correspondences& c, const std::vector<double>& w, int count,
                              std::uint32_t seed, double min_spread,
                              const std::function<void(const Eigen::Isometry3d&)>& visit);

/** |T p_s,i - p_t,i| for every row [m]. */
std::vector<double> residuals(const Correspondences& c, const Eigen::Isometry3d& T);

/** Result of a robust estimator. */
struct RigidEstimate {
  enum class Status { Ok, TooFewMatches, DegenerateSamples, TooFewInliers, LargeResiduals };
  Status status = Status::TooFewMatches;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();  //!< maps source points into target
  std::vector<std::size_t> inliers;
  double scale = 0;                    //!< [m] noise scale of the inliers (MSSE sigma / RMS)
  std::size_t degenerate_samples = 0;  //!< hypotheses skipped as degenerate
  bool ok() const { return status == Status::Ok; }
};

const char* toString(RigidEstimate::Status s);

/** The same transform as an MRPT pose. */
mrpt::poses::CPose3D toPose(const Eigen::Isometry3d& T);
/** The same pose as an Eigen transform. */
Eigen::Isometry3d toIsometry(const mrpt::poses::CPose3D& pose);

}  // namespace hrgbd
