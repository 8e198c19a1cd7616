#include "rgbd_odometry/Is3dSampling.h"

#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include "rgbd_odometry/MsseEstimator.h"

namespace hrgbd {
namespace {

// Eq. (3): angle between two unit normals [rad].
double angle(const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
  return std::acos(std::clamp(static_cast<double>(a.dot(b)), -1.0, 1.0));
}

constexpr int kOrientationDim = 2;  // p of eq. (5): a direction has two degrees of freedom

}  // namespace

Is3dResult sampleIs3d(const Points& normals, const GeometricParams& p) {
  Is3dResult out;
  std::mt19937 rng(static_cast<std::uint32_t>(p.seed));
  const std::size_t k = std::max<std::size_t>(
      kOrientationDim + 1, static_cast<std::size_t>(std::ceil(p.is3d_k_fraction * normals.size())));
  const double max_angle = mrpt::DEG2RAD(p.is3d_max_group_angle_deg);
  std::vector<std::size_t> rest(normals.size());
  std::iota(rest.begin(), rest.end(), 0);

  std::vector<double> r2;
  while (static_cast<int>(out.groups.size()) < p.is3d_max_groups && rest.size() > k) {
    // Algorithm 1 lines 5-13: the reference with the least k'-th order squared residual.
    double best = std::numeric_limits<double>::infinity();
    std::size_t best_ref = rest.front();
    std::uniform_int_distribution<std::size_t> pick(0, rest.size() - 1);
    for (int i = 0; i < p.is3d_references; ++i) {
      const std::size_t ref = rest[pick(rng)];
      r2.resize(rest.size());
      for (std::size_t j = 0; j < rest.size(); ++j) {
        const double phi = angle(normals[ref], normals[rest[j]]);
        r2[j] = phi * phi;
      }
      std::nth_element(r2.begin(), r2.begin() + (k - 1), r2.end());
      if (r2[k - 1] < best) best = r2[k - 1], best_ref = ref;
    }
    if (std::sqrt(best) > max_angle) break;  // nothing dominant is left

    // Line 14: eqs. (4)-(5) on the winner's sorted residuals separate its group.
    std::vector<std::pair<double, std::size_t>> res(rest.size());
    for (std::size_t j = 0; j < rest.size(); ++j)
      res[j] = {angle(normals[best_ref], normals[rest[j]]), rest[j]};
    std::sort(res.begin(), res.end());
    std::vector<double> sorted(res.size());
    for (std::size_t j = 0; j < res.size(); ++j) sorted[j] = res[j].first;
    double sigma = 0;
    const std::size_t members = msseInlierCount(sorted, k, p.is3d_T, kOrientationDim, &sigma);
    // Growth through a continuum of orientations (the edges left after the planes) ends with a
    // wide scale: that is no dominant orientation either.
    if (sigma > max_angle) break;
    out.groups.push_back({normals[best_ref], members, mrpt::RAD2DEG(sigma)});
    rest.clear();
    for (std::size_t j = members; j < res.size(); ++j) rest.push_back(res[j].second);
  }

  // Lines 15-17: the points in no dominant group. When more than is3d_points remain, keep those
  // farthest (in angle) from every dominant orientation: a random subset would differ between
  // frames and halve the keypoints' repeatability (measured on the simulated zig-zag).
  out.candidates = rest.size();
  if (rest.size() > static_cast<std::size_t>(p.is3d_points)) {
    std::vector<std::pair<double, std::size_t>> ranked;
    for (const std::size_t j : rest) {
      double nearest = M_PI;
      for (const auto& g : out.groups) nearest = std::min(nearest, angle(g.normal, normals[j]));
      ranked.push_back({-nearest, j});
    }
    std::nth_element(ranked.begin(), ranked.begin() + p.is3d_points, ranked.end());
    rest.clear();
    for (int j = 0; j < p.is3d_points; ++j) rest.push_back(ranked[j].second);
  }
  std::sort(rest.begin(), rest.end());
  out.indices = std::move(rest);
  return out;
}

}  // namespace hrgbd
