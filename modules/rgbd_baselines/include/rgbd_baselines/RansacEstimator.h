#pragma once
/** \file RansacEstimator.h
 * Classic RANSAC rigid estimator, the paper's ORB+RANSAC baseline (section IV-C, Henry et al.).
 * Hand-written on the same sampler as MSSE: MRPT's se3_l2_robust votes on pose hypotheses and
 * needs >= 50 % inliers, so it is not the residual-threshold RANSAC the paper compares against. */
#include <mrpt/config/CLoadableOptions.h>

#include "rgbd_odometry/RigidFit.h"

namespace hrgbd {

/** Parameters of estimateRansac(). INI section [RANSAC]. */
struct RansacParams : public mrpt::config::CLoadableOptions {
  int iterations = 1000;           //!< random 3-point hypotheses
  double inlier_threshold = 0.03;  //!< [m] residual below which a match supports a hypothesis
  int min_matches = 10;            //!< fewer matches -> status TooFewMatches
  int min_inliers = 8;             //!< fewer inliers -> status TooFewInliers
  double min_spread = 0.01;        //!< [m] smallest triangle height of a usable sample
  int seed = 1;                    //!< random generator seed

  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};

/** Hypothesis with the most residuals under the threshold, refitted (unweighted) on them.
 * `scale` is the inliers' RMS residual [m]. */
RigidEstimate estimateRansac(const Correspondences& c, const RansacParams& params);

}  // namespace hrgbd
