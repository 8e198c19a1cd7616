#include "rgbd_baselines/RansacEstimator.h"

#include <cmath>

#include "rgbd_core/Config.h"

namespace hrgbd {

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
