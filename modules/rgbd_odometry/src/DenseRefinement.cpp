// Gauss-Newton on SE(3) over the pyramid: every known-depth pixel of the current frame is moved
// into the reference by T and projected; its photometric residual is I_ref(q) - I_cur(p), its
// geometric residual the distance to the reference's tangent plane at q (projective pairing).
#include "rgbd_odometry/DenseRefinement.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <optional>

#include "rgbd_core/Median.h"

namespace hrgbd {
namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

// Bilinear sampling at (u, v), inside [0, cols - 1) x [0, rows - 1), of images of one size:
// the cell and weights are found once for the intensity and both gradients. Taken in double and
// clamped: u = 638.99999999 rounded to float is 639, one past the last 2x2 cell
// (AddressSanitizer found it).
struct Bilinear {
  Bilinear(const cv::Mat& m, double u, double v)
      : u0(std::min(static_cast<int>(u), m.cols - 2)),
        v0(std::min(static_cast<int>(v), m.rows - 2)),
        a(static_cast<float>(u - u0)),
        b(static_cast<float>(v - v0)) {}
  float operator()(const cv::Mat& m) const {
    const float* r0 = m.ptr<float>(v0) + u0;
    const float* r1 = m.ptr<float>(v0 + 1) + u0;
    return (1 - b) * ((1 - a) * r0[0] + a * r0[1]) + b * ((1 - a) * r1[0] + a * r1[1]);
  }
  int u0, v0;
  float a, b;
};

// Jacobian of a residual whose derivative with respect to the moved point P is g, for a left
// perturbation exp(delta) T with delta = (translation, rotation). (`inline` here and on
// toMiddleRow: GCC called both out of line, 6 % of a fr1/rpy run.)
inline Vector6d jacobian(const Eigen::Vector3d& P, const Eigen::Vector3d& g) {
  Vector6d J;
  J << g, P.cross(g);
  return J;
}

// The point of the current frame with its intensity; `geometric`: it has a point-to-plane term.
struct CurrentPoint {
  Eigen::Vector3d P;  //!< at the frame time
  /** P moved so that T maps it where the reference saw it: at the time of the reference row it
   * lands on (undoes the reference's rolling shutter; P for a global shutter) */
  Eigen::Vector3d at_reference_rows;
  float grey;
  bool geometric;
};

// The time of image row v (pixel centres at integers) of `rows` in a readout: -0.5 the first
// row, 0.5 the last, 0 the frame time.
double rowFraction(double v, int rows) { return (v + 0.5) / rows - 0.5; }

// A point seen at row fraction s of a frame whose camera moved by `m` during the readout, in
// the camera frame of the middle row (first order: the motion of one readout is small).
inline Eigen::Vector3d toMiddleRow(const Eigen::Vector3d& P, double s, const ReadoutMotion& m) {
  return P + s * (m.tail<3>().cross(P) + m.head<3>());
}

// Every pixel with depth, at the frame time (rolling shutter undone with `readout`); the
// point-to-plane term on every `stride`-th row and column.
// (Leaving out the pixels without texture in the current image as well, unless they have the
// point-to-plane term, was 7 % faster and better on teddy, 0.0097 -> 0.0077 m, but worse on the
// fast rotation of fr1/rpy, 0.0260 -> 0.0280 m: motion blur hides texture the reference has.)
std::vector<CurrentPoint> currentPoints(const DenseLevel& c, int stride,
                                        const ReadoutMotion& readout) {
  std::vector<CurrentPoint> pts;
  pts.reserve(c.depth.total());
  const bool rolling = !readout.isZero();
  for (int v = 0; v < c.depth.rows; ++v) {
    const double s = rowFraction(v, c.depth.rows);
    for (int u = 0; u < c.depth.cols; ++u) {
      const float z = c.depth.at<float>(v, u);
      if (!std::isfinite(z)) continue;
      const Eigen::Vector3d P = c.cam.backProject(u, v, z);
      const Eigen::Vector3d Pt = rolling ? toMiddleRow(P, s, readout) : P;
      pts.push_back({Pt, Pt, c.grey.at<float>(v, u), u % stride == 0 && v % stride == 0});
    }
  }
  return pts;
}

// The noise sigmas that normalise the residuals at one level.
struct NoiseScales {
  double photometric = 1;  //!< [grey levels]
  double depth_noise = 0;  //!< [1/m] depth sigma / z^2
};

/** The smallest depth noise factor taken from the residuals, as a share of the model's: keeps
 * the point-to-plane term from swamping the intensity term on exact renders. */
constexpr double kCleanestDepth = 0.02;
/** Fewer point-to-plane pairs give no measured scale: the model's. */
constexpr std::size_t kMinDepthPairs = 100;
/** On a level with at least kSampledLevel points with a point-to-plane term, the noise scales
 * are medians over every kScaleSampleStep-th point in row order (of the point-to-plane pairs
 * every 2nd to every 4th, as the columns fall): the same scales to a few per cent, and the pass
 * costs a quarter (fr1/rpy: the refinement's median per frame 0.81 times as long with the
 * `inline`s above). A smaller level, cheap anyway, takes every point, so that its measured depth
 * scale still needs kMinDepthPairs pairs, not a quarter of them. */
constexpr std::size_t kScaleSampleStep = 4;
constexpr std::size_t kSampledLevel = 40 * kMinDepthPairs;

// The Gauss-Newton system of one evaluation: H delta = -b, and the mean robust cost.
struct NormalEquations {
  Matrix6d H = Matrix6d::Zero();
  Vector6d b = Vector6d::Zero();
  double cost = 0;
  /** Comparable between poses: every (point, term) slot costs the Huber cost capped at
   * e = 3 huber, a point without a pair the cap; mean over the slots. */
  double score = 0;
  std::size_t photometric = 0, geometric = 0;         //!< pairs
  Eigen::Matrix3d normals = Eigen::Matrix3d::Zero();  //!< sum of n n^T over geometric pairs
};

class LevelSolver {
 public:
  LevelSolver(const DenseLevel& cur, const DenseLevel& ref, const DenseParams& p, int stride,
              const ReadoutMotion& cur_readout, const ReadoutMotion& ref_readout)
      : m_ref(ref),
        m_p(p),
        m_points(currentPoints(cur, stride, cur_readout)),
        m_ref_readout(ref_readout),
        m_geometric_points(static_cast<std::size_t>(std::count_if(
            m_points.begin(), m_points.end(), [](const auto& q) { return q.geometric; }))),
        m_geometric_weight(p.geometric_weight * stride * stride),
        m_skip_untextured(!ref.textured.empty() && p.min_gradient >= ref.textured_gradient) {}

  double fx() const { return m_ref.cam.fx; }  //!< [px] of the level

  // Undoes the reference's rolling shutter for motions near T: each point is moved by the
  // reference's motion between the frame time and the row T maps it to, taken into the current
  // frame. Fixed for a level's iterations (a step moves the row by about a pixel at the finest
  // level, the correction by that share of one readout's motion).
  void startAt(const Eigen::Isometry3d& T) {
    if (m_ref_readout.isZero()) return;
    const auto& c = m_ref.cam;
    const Eigen::Matrix3d Rt = T.rotation().transpose();
    for (auto& pt : m_points) {
      const Eigen::Vector3d X = T * pt.P;
      if (X.z() <= 0) {  // behind the reference: never paired, but no other start's correction
        pt.at_reference_rows = pt.P;
        continue;
      }
      const double s = rowFraction(c.fy * X.y() / X.z() + c.cy, c.height);
      pt.at_reference_rows = pt.P - Rt * (toMiddleRow(X, s, m_ref_readout) - X);
    }
  }

  // The noise scales at T, from one pass over the pairs (1.4826 x the median absolute residual):
  // the intensity's (at least one grey level), and the depth noise factor: the model's, or, when
  // the point-to-plane residuals say the depth is much cleaner (see clean_depth_fraction), theirs.
  NoiseScales noiseScales(const Eigen::Isometry3d& T) const {
    std::vector<float> photo, depth;  // |residual|; |point-to-plane residual| / z^2 / sqrt(2)
    const bool measure_depth = m_p.clean_depth_fraction > 0 && m_p.geometric_weight > 0;
    const std::size_t step = m_geometric_points >= kSampledLevel ? kScaleSampleStep : 1;
    photo.reserve(m_points.size() / step + 1);
    if (measure_depth) depth.reserve(m_geometric_points / step + 1);
    forEachPair(
        T,
        [&](const Eigen::Vector3d& P, double iz, double u, double v, int ui, int vi, float zr,
            float grey, bool geometric) {
          photo.push_back(std::abs(Bilinear(m_ref.grey, u, v)(m_ref.grey) - grey));
          if (!measure_depth || !geometric) return;
          if (const auto plane = tangentPlane(P, ui, vi, zr))
            depth.push_back(
                static_cast<float>(std::abs(plane->distance) * iz * iz / std::sqrt(2.0)));
        },
        step);
    NoiseScales s;
    s.photometric = photo.empty() ? 1 : std::max(1.0, 1.4826 * median(photo));
    s.depth_noise = m_p.depth_noise;
    if (depth.size() >= kMinDepthPairs) {
      const double measured = 1.4826 * median(depth);
      if (measured < m_p.clean_depth_fraction * m_p.depth_noise)
        s.depth_noise = std::max(measured, kCleanestDepth * m_p.depth_noise);
    }
    return s;
  }

  // Normal equations of the Huber-weighted, noise-normalised residuals of both terms at T.
  NormalEquations normalEquations(const Eigen::Isometry3d& T, const NoiseScales& scales) const {
    NormalEquations n;
    const double k = m_p.huber, cap = 2.5 * k * k;  // Huber cost at e = 3k
    // inv_sigma: 1 / the residual's noise sigma
    auto add = [&](const Vector6d& J, double r, double inv_sigma, double weight) {
      const double e = std::abs(r) * inv_sigma;
      const double w = weight * (e <= k ? 1 : k / e) * inv_sigma * inv_sigma;
      // the lower triangle only (H is symmetric; completed below)
      for (int j = 0; j < 6; ++j) {
        const double wj = w * J[j];
        for (int i = j; i < 6; ++i) n.H(i, j) += wj * J[i];
        n.b[j] += wj * r;
      }
      const double rho = e <= k ? 0.5 * e * e : k * (e - 0.5 * k);
      n.cost += weight * rho;
      n.score += std::min(rho, cap);
    };
    const auto& c = m_ref.cam;
    const double inv_photo_sigma = 1 / scales.photometric;
    // 1 / the sigma of a point-to-plane residual at 1 m (below)
    const double inv_depth_sigma = 1 / (std::sqrt(2.0) * scales.depth_noise);
    forEachPair(T, [&](const Eigen::Vector3d& P, double iz, double u, double v, int ui, int vi,
                       float zr, float grey, bool geometric) {
      const Bilinear at(m_ref.grey, u, v);
      if (m_p.photometric_weight > 0 &&
          (!m_skip_untextured || m_ref.textured.at<uchar>(at.v0, at.u0))) {
        const double gx = at(m_ref.gx), gy = at(m_ref.gy);
        if (gx * gx + gy * gy >= m_p.min_gradient * m_p.min_gradient) {
          const Eigen::Vector3d g(gx * c.fx * iz, gy * c.fy * iz,
                                  -(gx * c.fx * P.x() + gy * c.fy * P.y()) * iz * iz);
          add(jacobian(P, g), at(m_ref.grey) - grey, inv_photo_sigma, m_p.photometric_weight);
          ++n.photometric;
        }
      }
      if (m_p.geometric_weight <= 0 || !geometric) return;
      const auto plane = tangentPlane(P, ui, vi, zr);
      if (!plane) return;
      // both depths are noisy: the sigma of the difference of two readings at about this depth
      const double inv_sigma = iz * iz * inv_depth_sigma;
      add(jacobian(P, plane->normal), plane->distance, inv_sigma, m_geometric_weight);
      ++n.geometric;
      n.normals.noalias() += plane->normal * plane->normal.transpose();
    });
    n.H = n.H.selfadjointView<Eigen::Lower>();
    const std::size_t pairs = n.photometric + n.geometric;
    const std::size_t slots = (m_p.photometric_weight > 0 ? m_points.size() : 0) +
                              (m_p.geometric_weight > 0 ? m_geometric_points : 0);
    n.cost /= std::max<std::size_t>(1, pairs);
    n.score = slots ? (n.score + (slots - pairs) * cap) / slots : cap;
    return n;
  }

 private:
  struct TangentPlane {
    Eigen::Vector3d normal;  //!< the reference's, unit
    double distance;         //!< [m] of the point from the plane, signed
  };
  // The reference's tangent plane at pixel (ui, vi) of depth zr, and P's distance from it; none
  // where the depth or the normal is unknown.
  std::optional<TangentPlane> tangentPlane(const Eigen::Vector3d& P, int ui, int vi,
                                           float zr) const {
    if (!std::isfinite(zr)) return std::nullopt;
    const cv::Vec3f nv = m_ref.normals.at<cv::Vec3f>(vi, ui);
    if (!std::isfinite(nv[0])) return std::nullopt;
    const Eigen::Vector3d n(nv[0], nv[1], nv[2]);
    return TangentPlane{n, n.dot(P - m_ref.cam.backProject(ui, vi, zr))};
  }

  // Calls f(P, 1 / P.z, u, v, ui, vi, z_ref, grey, geometric) for every `step`-th current point
  // that T moves into the reference image without landing in front of or behind the reference
  // depth (occlusion gate; unknown reference depth passes, for the photometric term).
  template <class F>
  void forEachPair(const Eigen::Isometry3d& T, F f, std::size_t step = 1) const {
    const auto& c = m_ref.cam;
    for (std::size_t i = 0; i < m_points.size(); i += step) {
      const CurrentPoint& pt = m_points[i];
      const Eigen::Vector3d P = T * pt.at_reference_rows;
      if (P.z() <= 0) continue;
      const double iz = 1 / P.z();
      const double u = c.fx * P.x() * iz + c.cx, v = c.fy * P.y() * iz + c.cy;
      if (!(u >= 0 && v >= 0 && u < c.width - 1 && v < c.height - 1)) continue;
      const int ui = static_cast<int>(u + 0.5), vi = static_cast<int>(v + 0.5);
      const float zr = m_ref.depth.at<float>(vi, ui);
      if (std::abs(zr - P.z()) > m_p.max_depth_difference) continue;  // false for NaN
      f(P, iz, u, v, ui, vi, zr, pt.grey, pt.geometric);
    }
  }

  const DenseLevel& m_ref;
  const DenseParams& m_p;
  std::vector<CurrentPoint> m_points;
  ReadoutMotion m_ref_readout;         //!< the reference's motion during its readout
  std::size_t m_geometric_points = 0;  //!< of them, with a point-to-plane term
  /** each point-to-plane pair stands for stride^2 pixels: the terms keep their balance */
  double m_geometric_weight = 0;
  /** the reference's textured cells were made for this min_gradient or a lower one */
  bool m_skip_untextured = false;
};

Eigen::Isometry3d expSe3(const Vector6d& d) {
  Eigen::Isometry3d E = Eigen::Isometry3d::Identity();
  const Eigen::Vector3d w = d.tail<3>();
  if (w.norm() > 0) E.linear() = Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix();
  E.translation() = d.head<3>();
  return E;
}

// Gauss-Newton at one level from T; returns the last evaluation: at the returned T, or one
// converged step (under converged_px) before it.
NormalEquations solveLevel(LevelSolver& solver, Eigen::Isometry3d& T, const DenseParams& p,
                           int& iterations, NoiseScales& scales) {
  solver.startAt(T);
  scales = solver.noiseScales(T);  // fixed per level
  NormalEquations n = solver.normalEquations(T, scales);
  for (int it = 0; it < p.iterations && n.photometric + n.geometric >= 6; ++it) {
    const Vector6d delta = n.H.ldlt().solve(-n.b);
    if (!delta.allFinite()) break;
    const Eigen::Isometry3d next = expSe3(delta) * T;
    // converged (the image moves by under converged_px): the step is taken without an
    // evaluation of its own (the level would end after it whether accepted or refused)
    if (delta.norm() * solver.fx() < p.converged_px) {
      T = next;
      break;
    }
    NormalEquations n2 = solver.normalEquations(next, scales);
    ++iterations;
    if (n2.cost > n.cost) break;  // a step uphill: keep the previous estimate
    T = next, n = n2;
  }
  return n;
}

// Whether two refinements of different starts have met at a level: within two converged steps
// there (`step`: converged_px / fx of the level; metres and radians together). On fr1/rpy 57 of
// the 70 frames with two starts ended within 0.5 mm and 0.03 deg; dropping the later start once a
// level brings it there took 12 % off the refinement's time over the sequence with the same ATE on
// every real folder and the simulated suite. (A fixed 0.5 mm is too tight once the coarser
// levels stop at their own precision: the starts were then both refined to the finest level.)
bool together(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, double step) {
  const Eigen::Isometry3d d = a.inverse() * b;
  const double t = d.translation().norm(), w = Eigen::AngleAxisd(d.rotation()).angle();
  return t * t + w * w < 4 * step * step;
}

}  // namespace

DenseResult refineDense(const DensePyramid& cur, const DensePyramid& ref,
                        const std::vector<Eigen::Isometry3d>& starts, const DenseParams& p,
                        const ReadoutMotion& cur_readout, const ReadoutMotion& ref_readout) {
  DenseResult out;
  if (starts.empty() || cur.levels.empty() || cur.levels.size() != ref.levels.size()) {
    out.detail = "dense refinement: no start or pyramids of different depth";
    return out;
  }
  out.T = starts.front();
  if (!std::all_of(ref.levels.begin(), ref.levels.end(), hasDerivatives)) {
    out.detail = "dense refinement: the reference pyramid has no derivatives (addDerivatives)";
    return out;
  }
  std::vector<LevelSolver> solvers;
  for (std::size_t l = 0; l < cur.levels.size(); ++l)
    solvers.emplace_back(cur.levels[l], ref.levels[l], p, l == 0 ? p.geometric_stride : 1,
                         cur_readout, ref_readout);
  // every start is refined coarse to fine, level by level; the best score at the finest wins
  struct Refined {
    std::size_t start;  // its index in starts
    Eigen::Isometry3d T;
    NormalEquations n;
    NoiseScales scales;              // at the finest level
    Eigen::Isometry3d finest_start;  // where the finest level started (its startAt())
  };
  std::vector<Refined> refined;
  for (std::size_t i = 0; i < starts.size(); ++i)
    refined.push_back({i, starts[i], {}, {}, starts[i]});
  for (int l = static_cast<int>(solvers.size()) - 1; l >= 0; --l) {
    for (auto& r : refined) {
      if (l == 0) r.finest_start = r.T;
      r.n = solveLevel(solvers[l], r.T, p, out.iterations, r.scales);
    }
    // a start that a level brought next to an earlier one would follow it through the finer
    // levels: only the earlier one goes on
    const double step = p.converged_px / solvers[l].fx();  // a converged step there
    for (std::size_t j = refined.size(); l > 0 && j-- > 1;)
      if (std::any_of(refined.begin(), refined.begin() + static_cast<std::ptrdiff_t>(j),
                      [&](const Refined& r) { return together(r.T, refined[j].T, step); }))
        refined.erase(refined.begin() + static_cast<std::ptrdiff_t>(j));
  }
  // scored on one depth scale, the most lenient of the starts' that reached the finest level: a
  // start still far off measures the model's, and its rival judged on an exact depth's would lose
  // on the capped costs (a dropped start was where the one it joined is, with its scale)
  double depth_noise = 0;
  for (const auto& r : refined) depth_noise = std::max(depth_noise, r.scales.depth_noise);
  double best = 1e300;
  Eigen::Isometry3d T = starts.front();
  for (std::size_t i = 0; i < refined.size(); ++i) {
    const auto& [start, Ti, n0, scales, finest_start] = refined[i];
    NormalEquations n = n0;
    if (scales.depth_noise < depth_noise) {
      solvers.front().startAt(finest_start);  // this start's rolling-shutter correction
      n = solvers.front().normalEquations(Ti, {scales.photometric, depth_noise});
    }
    if (n.score < best) {
      best = n.score, T = Ti, out.start = start;
      out.photometric_pairs = n.photometric, out.geometric_pairs = n.geometric;
      out.normal_spread =
          n.geometric ? Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(n.normals / n.geometric)
                            .eigenvalues()(0)
                      : 0;
    }
  }
  // pixels paired: each point-to-plane pair stands for geometric_stride^2 pixels
  const std::size_t stride2 = static_cast<std::size_t>(p.geometric_stride * p.geometric_stride);
  if (out.photometric_pairs + stride2 * out.geometric_pairs <
      static_cast<std::size_t>(p.min_pixels)) {
    out.detail = "dense refinement: " + std::to_string(out.photometric_pairs) + " photometric + " +
                 std::to_string(out.geometric_pairs) + " geometric pairs < min_pixels";
    return out;
  }
  out.ok = true;
  out.T = T;
  return out;
}

}  // namespace hrgbd
