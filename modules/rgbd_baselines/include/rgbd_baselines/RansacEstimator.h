#pragma once
/** \file RansacEstimator.h
 * Classic RANSAC rigid estimator, the paper's ORB+RANSAC baseline (section IV-C, Henry et al.).
 * Hand-written on the same sampler as MSSE: MRPT's se3_l2_robust votes on pose hypotheses and
 * needs >= 50 % inliers, so it is not the residual-threshold RANSAC the paper compares against. */
#include "rgbd_core/Params.h"
#include "rgbd_odometry/RigidFit.h"

namespace hrgbd {

/** Parameters of estimateRansac(). INI section [RANSAC]. */
struct RansacParams : public Params<RansacParams> {
  int iterations = 1000;           //!< random 3-point hypotheses
  double inlier_threshold = 0.03;  //!< [m] residual below which a match supports a hypothesis
  int min_matches = 10;            //!< fewer matches -> status TooFewMatches
  int min_inliers = 8;             //!< fewer inliers -> status TooFewInliers
  double min_spread = 0.01;        //!< [m] smallest triangle height of a usable sample
  int seed = 1;                    //!< random generator seed

  template <class P, class V>
  static void declare(P& p, V& v) {
    HRGBD_PARAM(iterations, "random 3-point hypotheses", Range::closed(1, 1000000));
    HRGBD_PARAM(inlier_threshold, "[m] inlier residual threshold", Range::above(0));
    HRGBD_PARAM(min_matches, "fewer matches: frame not registered", Range::atLeast(3));
    HRGBD_PARAM(min_inliers, "fewer inliers: frame not registered", Range::atLeast(3));
    HRGBD_PARAM(min_spread, "[m] smallest triangle height of a sample", Range::atLeast(0));
    HRGBD_PARAM(seed, "random seed");
  }
};

/** Hypothesis with the most residuals under the threshold, refitted (unweighted) on them.
 * `scale` is the inliers' RMS residual [m]. */
RigidEstimate estimateRansac(const Correspondences& c, const RansacParams& params);

}  // namespace hrgbd
