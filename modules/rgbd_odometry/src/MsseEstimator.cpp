#include "rgbd_odometry/MsseEstimator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rgbd_core/Config.h"

namespace hrgbd {

void MsseParams::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) {
  rejectUnknownKeys(c, s,
                    {"hypotheses", "k_fraction", "T", "min_matches", "min_inliers", "min_spread",
                     "depth_weighting", "seed", "max_scale"});
  MRPT_LOAD_CONFIG_VAR_CS(hypotheses, int);
  MRPT_LOAD_CONFIG_VAR_CS(k_fraction, double);
  MRPT_LOAD_CONFIG_VAR_CS(T, double);
  MRPT_LOAD_CONFIG_VAR_CS(min_matches, int);
  MRPT_LOAD_CONFIG_VAR_CS(min_inliers, int);
  MRPT_LOAD_CONFIG_VAR_CS(min_spread, double);
  MRPT_LOAD_CONFIG_VAR_CS(depth_weighting, bool);
  MRPT_LOAD_CONFIG_VAR_CS(seed, int);
  MRPT_LOAD_CONFIG_VAR_CS(max_scale, double);
  requireValid(hypotheses >= 1, s, "hypotheses", hypotheses, "must be >= 1");
  requireValid(k_fraction > 0 && k_fraction <= 1, s, "k_fraction", k_fraction, "must be in (0, 1]");
  requireValid(T > 0, s, "T", T, "must be > 0");
  requireValid(min_matches >= 7, s, "min_matches", min_matches, "must be >= 7 (p = 6 plus one)");
  requireValid(min_inliers >= 3, s, "min_inliers", min_inliers, "must be >= 3");
  requireValid(min_spread >= 0, s, "min_spread", min_spread, "must be >= 0 m");
  requireValid(max_scale > 0, s, "max_scale", max_scale, "must be > 0 m");
}

void MsseParams::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const {
  MRPT_SAVE_CONFIG_VAR_COMMENT(hypotheses, "random 3-point hypotheses");
  MRPT_SAVE_CONFIG_VAR_COMMENT(k_fraction, "k' / number of matches (least k'-th order residual)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(T, "MSSE threshold of eq. (4)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_matches, "fewer matches: frame not registered");
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_inliers, "fewer inliers: frame not registered");
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_spread, "[m] smallest triangle height of a 3-point sample");
  MRPT_SAVE_CONFIG_VAR_COMMENT(depth_weighting, "weights 1/(zs^2+zt^2) in eq. (6)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(seed, "random seed");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_scale, "[m] larger inlier sigma: fit rejected");
}

std::size_t msseInlierCount(const std::vector<double>& r, std::size_t k, double T, int p,
                            double* sigma_out) {
  const std::size_t n = r.size();
  k = std::clamp<std::size_t>(k, p + 1, n);
  double sum2 = 0;
  for (std::size_t j = 0; j < k; ++j) sum2 += r[j] * r[j];
  std::size_t i = k;  // inliers so far: r[0..i-1]
  double sigma = std::sqrt(sum2 / (i - p));
  while (i < n && r[i] <= T * sigma) {  // eq. (4): stop at the first |r_{i+1}| > T sigma_i
    sum2 += r[i] * r[i];
    ++i;
    sigma = std::sqrt(sum2 / (i - p));  // eq. (5)
  }
  if (sigma_out) *sigma_out = sigma;
  return i;
}

RigidEstimate estimateMsse(const Correspondences& c, const MsseParams& p) {
  RigidEstimate out;
  const std::size_t n = c.size();
  if (n < static_cast<std::size_t>(p.min_matches)) return out;
  constexpr int kModelDim = 6;
  const std::size_t k =
      std::clamp<std::size_t>(static_cast<std::size_t>(p.k_fraction * n), kModelDim + 1, n);
  const auto w = depthWeights(c, p.depth_weighting);

  // Least k-th order squared residual over the hypotheses.
  double best = std::numeric_limits<double>::infinity();
  std::vector<double> r2(n);
  out.degenerate_samples =
      forEachHypothesis(c, w, p.hypotheses, static_cast<std::uint32_t>(p.seed), p.min_spread,
                        [&](const Eigen::Isometry3d& T) {
                          std::size_t below = 0;
                          for (std::size_t i = 0; i < n; ++i) {
                            r2[i] = (T * c.source[i] - c.target[i]).squaredNorm();
                            below += r2[i] < best;
                          }
                          // Fewer than k residuals below the best: its k-th order residual
                          // cannot win, so the selection is skipped (same result, faster).
                          if (below < k) return;
                          std::nth_element(r2.begin(), r2.begin() + (k - 1), r2.end());
                          if (r2[k - 1] < best) best = r2[k - 1], out.T = T;
                        });
  if (!std::isfinite(best)) {
    out.status = RigidEstimate::Status::DegenerateSamples;
    return out;
  }

  // MSSE inlier growth on the winner's sorted residuals, then the refit on the inliers.
  const auto r = residuals(c, out.T);
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return r[a] < r[b]; });
  std::vector<double> sorted(n);
  for (std::size_t i = 0; i < n; ++i) sorted[i] = r[order[i]];
  const auto count = msseInlierCount(sorted, k, p.T, kModelDim, &out.scale);
  out.inliers.assign(order.begin(), order.begin() + count);
  std::sort(out.inliers.begin(), out.inliers.end());
  if (out.inliers.size() < static_cast<std::size_t>(p.min_inliers)) {
    out.status = RigidEstimate::Status::TooFewInliers;
    return out;
  }
  out.T = fitRigidWeighted(c, w, out.inliers);
  out.status =
      out.scale > p.max_scale ? RigidEstimate::Status::LargeResiduals : RigidEstimate::Status::Ok;
  return out;
}

}  // namespace hrgbd
