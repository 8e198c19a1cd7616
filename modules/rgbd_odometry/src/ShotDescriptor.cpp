#include "rgbd_odometry/ShotDescriptor.h"

#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>

namespace hrgbd {
namespace {

constexpr int kAzimuth = 8, kElevation = 2, kRadial = 2;

// Linear interpolation between two adjacent bins of a division with `n` bins spanning [0, n):
// `pos` is in bin units; returns the lower bin and the weight of the upper one. Values beyond the
// outer bin centres go wholly to the outer bin unless `wrap`.
struct Split {
  int lo, hi;
  float w_hi;
};
Split split(float pos, int n, bool wrap) {
  const float c = pos - 0.5f;  // relative to bin centres
  int lo = static_cast<int>(std::floor(c));
  float w = c - lo;
  if (wrap) return {(lo % n + n) % n, ((lo + 1) % n + n) % n, w};
  if (lo < 0) return {0, 0, 0};
  if (lo >= n - 1) return {n - 1, n - 1, 0};
  return {lo, lo + 1, w};
}

// Tombari et al. sign disambiguation: the axis points to where most neighbours are.
void disambiguate(Eigen::Vector3f& axis, const Points& pts,
                  const std::vector<std::pair<std::size_t, float>>& nbrs,
                  const Eigen::Vector3f& centre) {
  int positive = 0;
  for (const auto& [j, d2] : nbrs) positive += (pts[j] - centre).dot(axis) >= 0 ? 1 : -1;
  if (positive < 0) axis = -axis;
}

}  // namespace

bool shotLocalFrame(const Points& pts, const std::vector<std::pair<std::size_t, float>>& nbrs,
                    const Eigen::Vector3f& centre, float radius, Eigen::Matrix3f& frame) {
  if (nbrs.size() < 3) return false;
  Eigen::Matrix3f M = Eigen::Matrix3f::Zero();
  float wsum = 0;
  for (const auto& [j, d2] : nbrs) {
    const Eigen::Vector3f q = pts[j] - centre;
    const float w = radius - std::sqrt(d2);
    M += w * q * q.transpose();
    wsum += w;
  }
  if (!(wsum > 0)) return false;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3f> eig(M / wsum);
  Eigen::Vector3f x = eig.eigenvectors().col(2), z = eig.eigenvectors().col(0);
  disambiguate(x, pts, nbrs, centre);
  disambiguate(z, pts, nbrs, centre);
  frame.col(0) = x;
  frame.col(1) = z.cross(x);
  frame.col(2) = z;
  return true;
}

ShotResult computeShot(const Points& pts, const Points& normals, const PointKdTree& tree,
                       const std::vector<std::size_t>& keypoints, double radius_d,
                       int min_neighbours) {
  ShotResult out;
  const auto radius = static_cast<float>(radius_d);
  out.descriptors.create(0, kShotLength, CV_32F);
  std::vector<std::pair<std::size_t, float>> nbrs;
  std::array<float, kShotLength> hist;
  for (const std::size_t k : keypoints) {
    tree.radiusSearch(pts[k], radius, nbrs);
    Eigen::Matrix3f frame;
    if (static_cast<int>(nbrs.size()) < min_neighbours ||
        !shotLocalFrame(pts, nbrs, pts[k], radius, frame))
      continue;
    hist.fill(0);
    const Eigen::Vector3f z = frame.col(2);
    for (const auto& [j, d2] : nbrs) {
      const float d = std::sqrt(d2);
      if (d < 1e-6f) continue;  // the keypoint itself has no direction
      const Eigen::Vector3f l = frame.transpose() * (pts[j] - pts[k]);
      const float cos_theta = std::clamp(normals[j].dot(z), -1.0f, 1.0f);
      const float azimuth = std::atan2(l.y(), l.x());                       // (-pi, pi]
      const float elevation = std::atan2(l.z(), std::hypot(l.x(), l.y()));  // [-pi/2, pi/2]
      // Quadrilinear interpolation: cosine, azimuth (circular), elevation, radius.
      const Split c = split((cos_theta + 1.f) * 0.5f * kShotBins, kShotBins, false);
      const Split a = split((azimuth + float(M_PI)) / float(2 * M_PI) * kAzimuth, kAzimuth, true);
      const Split e =
          split((elevation + float(M_PI_2)) / float(M_PI) * kElevation, kElevation, false);
      const Split r = split(d / radius * kRadial, kRadial, false);
      for (int ir = 0; ir < 2; ++ir)
        for (int ie = 0; ie < 2; ++ie)
          for (int ia = 0; ia < 2; ++ia)
            for (int ic = 0; ic < 2; ++ic) {
              const float w = (ir ? r.w_hi : 1 - r.w_hi) * (ie ? e.w_hi : 1 - e.w_hi) *
                              (ia ? a.w_hi : 1 - a.w_hi) * (ic ? c.w_hi : 1 - c.w_hi);
              if (w == 0) continue;
              const int sector = ((ir ? r.hi : r.lo) * kElevation + (ie ? e.hi : e.lo)) * kAzimuth +
                                 (ia ? a.hi : a.lo);
              hist[sector * kShotBins + (ic ? c.hi : c.lo)] += w;
            }
    }
    cv::Mat row(1, kShotLength, CV_32F, hist.data());
    const double norm = cv::norm(row);
    if (!(norm > 0)) continue;
    out.descriptors.push_back(cv::Mat(row / norm));
    out.kept.push_back(k);
  }
  return out;
}

}  // namespace hrgbd
