#include "rgbd_odometry/MsseEstimator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rgbd_core/Config.h"

namespace hrgbd {
namespace {

// The correspondences' coordinates as separate arrays (x, y, z of the sources, then of the
// targets), so that the squared residuals of a hypothesis are one loop the compiler vectorises.
struct Columns {
  explicit Columns(const Correspondences& c) : n(c.size()), v(6 * c.size()) {
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k)
        v[k * n + i] = c.source[i][k], v[(3 + k) * n + i] = c.target[i][k];
  }
  const double* col(int k) const { return v.data() + k * n; }
  std::size_t n;
  std::vector<double> v;
};

// r2[i] = |T source_i - target_i|^2, computed as Eigen's T * p - q and squaredNorm() are (the same
// order of operations, no fused multiply-add: the same values); returns how many are below
// `best`. Clones for AVX-512 and AVX2 are chosen at load time.
__attribute__((target_clones("avx512f", "avx2", "default"), optimize("fp-contract=off")))
std::size_t
squaredResiduals(const Eigen::Isometry3d& T, const Columns& c, double best, double* r2) {
  const Eigen::Matrix3d R = T.linear();
  const Eigen::Vector3d t = T.translation();
  const double *sx = c.col(0), *sy = c.col(1), *sz = c.col(2);
  const double *tx = c.col(3), *ty = c.col(4), *tz = c.col(5);
  std::size_t below = 0;
  for (std::size_t i = 0; i < c.n; ++i) {
    const double x = R(0, 0) * sx[i] + R(0, 1) * sy[i] + R(0, 2) * sz[i] + t[0] - tx[i];
    const double y = R(1, 0) * sx[i] + R(1, 1) * sy[i] + R(1, 2) * sz[i] + t[1] - ty[i];
    const double z = R(2, 0) * sx[i] + R(2, 1) * sy[i] + R(2, 2) * sz[i] + t[2] - tz[i];
    r2[i] = x * x + y * y + z * z;
    below += r2[i] < best;
  }
  return below;
}

}  // namespace

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
  const Columns columns(c);
  out.degenerate_samples =
      forEachHypothesis(c, w, p.hypotheses, static_cast<std::uint32_t>(p.seed), p.min_spread,
                        [&](const Eigen::Isometry3d& T) {
                          const std::size_t below = squaredResiduals(T, columns, best, r2.data());
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
