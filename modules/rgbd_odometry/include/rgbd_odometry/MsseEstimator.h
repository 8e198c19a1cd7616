#pragma once
/** \file MsseEstimator.h
 * The MSSE robust rigid estimator (paper section III-G, eqs. 4-7; Bab-Hadiashar & Suter 1999).
 * No library here has it. */
#include "rgbd_core/Params.h"
#include "rgbd_odometry/RigidFit.h"

namespace hrgbd {

/** Parameters of estimateMsse(). INI section [MSSE]. */
struct MsseParams : public Params<MsseParams> {
  int hypotheses = 1000;  //!< random 3-point hypotheses
  /** k' as a fraction of the matches: hypotheses are ranked by their k'-th smallest squared
   * residual and MSSE grows the inliers from k'. A trade-off, measured: on fr3/teddy (ORB
   * matches ~85 % inliers) 0.5 gives aligned ATE 0.050-0.054 m over 4 seeds, 0.2 gives
   * 0.062-0.084 m; but 0.5 breaks down once outliers are a majority, while 0.2 survives 70 %
   * random outliers (MsseEstimator_test.BreakdownAgainstRansac). Use 0.2 for outlier-heavy
   * matching. */
  double k_fraction = 0.5;
  double T = 2.5;        //!< MSSE threshold, eq. (4): ~99 % of Gaussian inliers
  int min_matches = 10;  //!< fewer matches -> status TooFewMatches
  int min_inliers = 8;   //!< fewer inliers -> status TooFewInliers
  /** [m] inlier noise scale (sigma) above which the fit is rejected (status LargeResiduals):
   * with few matches eq. (5) alone accepts anything (seen: 10 matches, sigma = 0.6 m). Real
   * fr3/teddy frames reach 0.076 m (median 0.005 m) and still help, hence 0.15. */
  double max_scale = 0.15;
  double min_spread = 0.01;     //!< [m] smallest triangle height of a usable 3-point sample
  bool depth_weighting = true;  //!< eq. (6) weights from depth (else all 1)
  int seed = 1;                 //!< random generator seed (same seed, same result)

  template <class P, class V>
  static void declare(P& p, V& v) {
    HRGBD_PARAM(hypotheses, "random 3-point hypotheses", Range::closed(1, 1000000));
    HRGBD_PARAM(k_fraction, "k' / number of matches (least k'-th order residual)",
                Range::openClosed(0, 1));
    HRGBD_PARAM(T, "MSSE threshold of eq. (4)", Range::above(0));
    HRGBD_PARAM(min_matches, "fewer matches: frame not registered (p = 6 plus one at least)",
                Range::atLeast(7));
    HRGBD_PARAM(min_inliers, "fewer inliers: frame not registered", Range::atLeast(3));
    HRGBD_PARAM(min_spread, "[m] smallest triangle height of a 3-point sample", Range::atLeast(0));
    HRGBD_PARAM(depth_weighting, "weights 1/(zs^2+zt^2) in eq. (6)");
    HRGBD_PARAM(seed, "random seed");
    HRGBD_PARAM(max_scale, "[m] larger inlier sigma: fit rejected", Range::above(0));
  }
};

/** MSSE: hypotheses from random 3-tuples (eq. 6, weighted), the one with the least k'-th order
 * squared residual wins; its sorted residuals grow the inlier set from k' while
 * |r_{i+1}| <= T sigma_i (eqs. 4-5, model dimension p = 6); the transform is refitted on the
 * inliers. `scale` is the final sigma [m]. */
RigidEstimate estimateMsse(const Correspondences& c, const MsseParams& params);

/** Eqs. (4)-(5) on residuals sorted ascending: the number of inliers, growing from `k` while
 * r[i] <= T * sigma_{i} with sigma_i^2 = sum_{j<i} r_j^2 / (i - p). Writes the last sigma. */
std::size_t msseInlierCount(const std::vector<double>& sorted_residuals, std::size_t k, double T,
                            int p, double* sigma_out = nullptr);

}  // namespace hrgbd
