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

// Algorithm 1 lines 5-13: of `references` random candidates, the one with the least k'-th order
// squared angular residual over `rest`; returns it and that residual [rad^2]. The angle falls as
// the cosine rises, so the k'-th order statistic is taken on cosines and only it goes through
// acos (acos per pair was a quarter of the stage's time).
std::pair<std::size_t, double> bestReference(const Points& normals,
                                             const std::vector<std::size_t>& rest, std::size_t k,
                                             int references, std::mt19937& rng) {
  float best_cos = -2;
  std::size_t best_ref = rest.front();
  std::uniform_int_distribution<std::size_t> pick(0, rest.size() - 1);
  std::vector<float> neg_cos(rest.size());
  for (int i = 0; i < references; ++i) {
    const std::size_t ref = rest[pick(rng)];
    const Eigen::Vector3f& n = normals[ref];
    for (std::size_t j = 0; j < rest.size(); ++j) neg_cos[j] = -n.dot(normals[rest[j]]);
    std::nth_element(neg_cos.begin(), neg_cos.begin() + (k - 1), neg_cos.end());
    if (-neg_cos[k - 1] > best_cos) best_cos = -neg_cos[k - 1], best_ref = ref;
  }
  const double phi = std::acos(std::clamp(static_cast<double>(best_cos), -1.0, 1.0));
  return {best_ref, phi * phi};
}

// Line 14: eqs. (4)-(5) on the sorted residuals to `ref` separate its group, which is appended
// to `groups` and removed from `rest`. False (nothing changed) when the group's scale exceeds
// `max_angle`: growth through a continuum of orientations (the edges left after the planes) ends
// with a wide scale, and that is no dominant orientation either.
bool separateGroup(const Points& normals, std::size_t ref, std::size_t k, double T,
                   double max_angle, std::vector<std::size_t>& rest,
                   std::vector<DominantOrientation>& groups) {
  std::vector<std::pair<double, std::size_t>> res(rest.size());
  for (std::size_t j = 0; j < rest.size(); ++j)
    res[j] = {angle(normals[ref], normals[rest[j]]), rest[j]};
  std::sort(res.begin(), res.end());
  std::vector<double> sorted(res.size());
  for (std::size_t j = 0; j < res.size(); ++j) sorted[j] = res[j].first;
  double sigma = 0;
  const std::size_t members = msseInlierCount(sorted, k, T, kOrientationDim, &sigma);
  if (sigma > max_angle) return false;
  groups.push_back({normals[ref], members, mrpt::RAD2DEG(sigma)});
  rest.clear();
  for (std::size_t j = members; j < res.size(); ++j) rest.push_back(res[j].second);
  return true;
}

// The `count` points of `rest` farthest (in angle) from every dominant orientation: a random
// subset would differ between frames and halve the keypoints' repeatability (measured on the
// simulated zig-zag).
std::vector<std::size_t> farthestFromGroups(const Points& normals,
                                            const std::vector<std::size_t>& rest,
                                            const std::vector<DominantOrientation>& groups,
                                            int count) {
  std::vector<std::pair<float, std::size_t>> ranked;  // cosine to the nearest group, point
  for (const std::size_t j : rest) {
    float nearest = -1;
    for (const auto& g : groups) nearest = std::max(nearest, g.normal.dot(normals[j]));
    ranked.push_back({nearest, j});
  }
  std::nth_element(ranked.begin(), ranked.begin() + count, ranked.end());
  std::vector<std::size_t> out;
  for (int j = 0; j < count; ++j) out.push_back(ranked[j].second);
  return out;
}

}  // namespace

Is3dResult sampleIs3d(const Points& normals, const GeometricParams& p) {
  Is3dResult out;
  std::mt19937 rng(static_cast<std::uint32_t>(p.seed));
  const std::size_t k = std::max<std::size_t>(
      kOrientationDim + 1, static_cast<std::size_t>(std::ceil(p.is3d_k_fraction * normals.size())));
  const double max_angle = mrpt::DEG2RAD(p.is3d_max_group_angle_deg);
  std::vector<std::size_t> rest(normals.size());
  std::iota(rest.begin(), rest.end(), 0);
  while (static_cast<int>(out.groups.size()) < p.is3d_max_groups && rest.size() > k) {
    const auto [ref, best] = bestReference(normals, rest, k, p.is3d_references, rng);
    if (std::sqrt(best) > max_angle) break;  // nothing dominant is left
    if (!separateGroup(normals, ref, k, p.is3d_T, max_angle, rest, out.groups)) break;
  }
  // Lines 15-17: the points in no dominant group.
  out.candidates = rest.size();
  if (rest.size() > static_cast<std::size_t>(p.is3d_points))
    rest = farthestFromGroups(normals, rest, out.groups, p.is3d_points);
  std::sort(rest.begin(), rest.end());
  out.indices = std::move(rest);
  return out;
}

}  // namespace hrgbd
