#include "rgbd_odometry/PlaneIcp.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "rgbd_core/Median.h"

namespace hrgbd {

PlaneIcpResult refinePointToPlane(const Points& source, const Points& target, const Points& normals,
                                  const PointKdTree& tree, const Eigen::Isometry3d& initial,
                                  int iterations, double max_distance) {
  PlaneIcpResult out;
  out.T = initial;
  std::vector<Eigen::Vector3d> q(source.size()), n(source.size()), p(source.size());
  std::vector<double> e;
  for (out.iterations = 0; out.iterations < iterations; ++out.iterations) {
    // Pairs: nearest target point of each transformed source point.
    std::size_t m = 0;
    e.clear();
    for (const auto& s : source) {
      const Eigen::Vector3d ps = out.T * s.cast<double>();
      std::size_t j;
      float d2;
      if (!tree.nearest(ps.cast<float>(), j, d2) || d2 > max_distance * max_distance) continue;
      p[m] = ps, q[m] = target[j].cast<double>(), n[m] = normals[j].cast<double>();
      e.push_back(n[m].dot(p[m] - q[m]));
      ++m;
    }
    out.pairs = m;
    if (m < 6) return out;
    // Robust scale from the median absolute residual (1.4826 MAD), at least 1 mm.
    std::vector<double> a(e.size());
    std::transform(e.begin(), e.end(), a.begin(), [](double x) { return std::abs(x); });
    const double huber = 1.345 * std::max(1.4826 * median(a), 1e-3);
    // Normal equations of the linearised residual e + [p x n; n] . [w; t].
    Eigen::Matrix<double, 6, 6> H = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> g = Eigen::Matrix<double, 6, 1>::Zero();
    double sse = 0;
    for (std::size_t i = 0; i < m; ++i) {
      Eigen::Matrix<double, 6, 1> J;
      J << p[i].cross(n[i]), n[i];
      const double w = std::abs(e[i]) <= huber ? 1.0 : huber / std::abs(e[i]);
      H += w * J * J.transpose();
      g += w * J * e[i];
      sse += e[i] * e[i];
    }
    out.rms = std::sqrt(sse / m);
    H.diagonal().array() += 1e-6 * H.trace() / 6;  // damping: unconstrained directions stay put
    const Eigen::Matrix<double, 6, 1> x = -H.ldlt().solve(g);
    if (!x.allFinite()) return out;
    Eigen::Isometry3d step = Eigen::Isometry3d::Identity();
    const double angle = x.head<3>().norm();
    if (angle > 0) step.linear() = Eigen::AngleAxisd(angle, x.head<3>() / angle).toRotationMatrix();
    step.translation() = x.tail<3>();
    out.T = step * out.T;
    if (x.tail<3>().norm() < 1e-4 && angle < 1.7e-4) {
      out.converged = true;
      ++out.iterations;
      break;
    }
  }
  return out;
}

}  // namespace hrgbd
