#include "rgbd_odometry/RigidFit.h"

#include <Eigen/SVD>
#include <random>

namespace hrgbd {

Eigen::Isometry3d fitRigidWeighted(const Correspondences& c, const std::vector<double>& w,
                                   const std::vector<std::size_t>& idx) {
  const std::size_t n = idx.empty() ? c.size() : idx.size();
  auto row = [&](std::size_t k) { return idx.empty() ? k : idx[k]; };
  double wsum = 0;
  Eigen::Vector3d ms = Eigen::Vector3d::Zero(), mt = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < n; ++k) {
    const auto i = row(k);
    wsum += w[i], ms += w[i] * c.source[i], mt += w[i] * c.target[i];
  }
  ms /= wsum, mt /= wsum;
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  for (std::size_t k = 0; k < n; ++k) {
    const auto i = row(k);
    H += w[i] * (c.source[i] - ms) * (c.target[i] - mt).transpose();
  }
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
  D(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0 ? -1 : 1;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = svd.matrixV() * D * svd.matrixU().transpose();
  T.translation() = mt - T.linear() * ms;
  return T;
}

std::vector<double> depthWeights(const Correspondences& c, bool enabled) {
  std::vector<double> w(c.size(), 1.0);
  if (!enabled || c.size() == 0) return w;
  double sum = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const double zs = c.source[i].z(), zt = c.target[i].z();
    w[i] = 1.0 / (zs * zs + zt * zt + 1e-12);
    sum += w[i];
  }
  for (double& x : w) x *= c.size() / sum;
  return w;
}

bool isDegenerateTriple(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                        const Eigen::Vector3d& c, double min_spread) {
  const double area2 = (b - a).cross(c - a).norm();  // twice the triangle's area
  const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm(), 1e-12});
  return area2 / longest < min_spread;  // the smallest height of the triangle
}

std::size_t forEachHypothesis(const Correspondences& c, const std::vector<double>& w, int count,
                              std::uint32_t seed, double min_spread,
                              const std::function<void(const Eigen::Isometry3d&)>& visit) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, c.size() - 1);
  std::size_t degenerate = 0;
  std::vector<std::size_t> s(3);
  for (int h = 0; h < count; ++h) {
    s[0] = pick(rng);
    do s[1] = pick(rng);
    while (s[1] == s[0]);
    do s[2] = pick(rng);
    while (s[2] == s[0] || s[2] == s[1]);
    if (isDegenerateTriple(c.source[s[0]], c.source[s[1]], c.source[s[2]], min_spread) ||
        isDegenerateTriple(c.target[s[0]], c.target[s[1]], c.target[s[2]], min_spread)) {
      ++degenerate;
      continue;
    }
    visit(fitRigidWeighted(c, w, s));
  }
  return degenerate;
}

std::vector<double> residuals(const Correspondences& c, const Eigen::Isometry3d& T) {
  std::vector<double> r(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) r[i] = (T * c.source[i] - c.target[i]).norm();
  return r;
}

namespace {

// The rotation made orthonormal again: chained products drift from it by rounding, and a drift
// fed back through the motion prediction grows without bound.
Eigen::Isometry3d orthonormal(const Eigen::Matrix4d& m) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::Quaterniond(m.topLeftCorner<3, 3>()).normalized().toRotationMatrix();
  T.translation() = m.topRightCorner<3, 1>();
  return T;
}

}  // namespace

mrpt::poses::CPose3D toPose(const Eigen::Isometry3d& T) {
  return mrpt::poses::CPose3D(mrpt::math::CMatrixDouble44(orthonormal(T.matrix()).matrix()));
}

Eigen::Isometry3d toIsometry(const mrpt::poses::CPose3D& pose) {
  return orthonormal(pose.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>().asEigen());
}

const char* toString(RigidEstimate::Status s) {
  switch (s) {
    case RigidEstimate::Status::Ok:
      return "ok";
    case RigidEstimate::Status::TooFewMatches:
      return "too_few_matches";
    case RigidEstimate::Status::DegenerateSamples:
      return "degenerate_samples";
    case RigidEstimate::Status::TooFewInliers:
      return "too_few_inliers";
    case RigidEstimate::Status::LargeResiduals:
      return "large_residuals";
  }
  return "?";
}

}  // namespace hrgbd
