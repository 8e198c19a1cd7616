#include "rgbd_baselines/RansacEstimator.h"

#include <cmath>

#include "rgbd_core/Config.h"

namespace hrgbd {

void RansacParams::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                      const std::string& s) {
  rejectUnknownKeys(
      c, s, {"iterations", "inlier_threshold", "min_matches", "min_inliers", "min_spread", "seed"});
  MRPT_LOAD_CONFIG_VAR_CS(iterations, int);
  MRPT_LOAD_CONFIG_VAR_CS(inlier_threshold, double);
  MRPT_LOAD_CONFIG_VAR_CS(min_matches, int);
  MRPT_LOAD_CONFIG_VAR_CS(min_inliers, int);
  MRPT_LOAD_CONFIG_VAR_CS(min_spread, double);
  MRPT_LOAD_CONFIG_VAR_CS(seed, int);
  requireValid(iterations >= 1, s, "iterations", iterations, "must be >= 1");
  requireValid(inlier_threshold > 0, s, "inlier_threshold", inlier_threshold, "must be > 0 m");
  requireValid(min_matches >= 3, s, "min_matches", min_matches, "must be >= 3");
  requireValid(min_inliers >= 3, s, "min_inliers", min_inliers, "must be >= 3");
  requireValid(min_spread >= 0, s, "min_spread", min_spread, "must be >= 0 m");
}

void RansacParams::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const {
  MRPT_SAVE_CONFIG_VAR_COMMENT(iterations, "random 3-point hypotheses");
  MRPT_SAVE_CONFIG_VAR_COMMENT(inlier_threshold, "[m] inlier residual threshold");
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_matches, "fewer matches: frame not registered");
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_inliers, "fewer inliers: frame not registered");
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_spread, "[m] smallest triangle height of a sample");
  MRPT_SAVE_CONFIG_VAR_COMMENT(seed, "random seed");
}

RigidEstimate estimateRansac(const Correspondences& c, const RansacParams& p) {
  RigidEstimate out;
  const std::size_t n = c.size();
  if (n < static_cast<std::size_t>(p.min_matches)) return out;
  const std::vector<double> w(n, 1.0);
  const double thr2 = p.inlier_threshold * p.inlier_threshold;
  std::size_t best = 0;
  bool any = false;
  out.degenerate_samples =
      forEachHypothesis(c, w, p.iterations, static_cast<std::uint32_t>(p.seed), p.min_spread,
                        [&](const Eigen::Isometry3d& T) {
                          any = true;
                          std::size_t support = 0;
                          for (std::size_t i = 0; i < n; ++i)
                            support += (T * c.source[i] - c.target[i]).squaredNorm() < thr2;
                          if (support > best) best = support, out.T = T;
                        });
  if (!any) {
    out.status = RigidEstimate::Status::DegenerateSamples;
    return out;
  }
  const auto r = residuals(c, out.T);
  double sum2 = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (r[i] < p.inlier_threshold) out.inliers.push_back(i), sum2 += r[i] * r[i];
  if (out.inliers.size() < static_cast<std::size_t>(p.min_inliers)) {
    out.status = RigidEstimate::Status::TooFewInliers;
    return out;
  }
  out.scale = std::sqrt(sum2 / out.inliers.size());
  out.T = fitRigidWeighted(c, w, out.inliers);
  out.status = RigidEstimate::Status::Ok;
  return out;
}

}  // namespace hrgbd
