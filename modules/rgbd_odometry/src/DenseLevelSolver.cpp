// Gauss-Newton on SE(3) over the pyramid: every known-depth pixel of the current frame is moved
// into the reference by T and projected; its photometric residual is I_ref(q) - I_cur(p), its
// geometric residual the distance to the reference's tangent plane at q (projective pairing).
#include "DenseLevelSolver.h"

#include <algorithm>
#include <cmath>

#include "rgbd_core/Median.h"

namespace hrgbd::dense {
namespace {

// The reference's 2x2 cell holding (u, v), inside [0, cols - 1) x [0, rows - 1), read from its
// interleaved (grey, gx, gy, 0) samples, and its pixel nearest to (u, v). The cell is found in
// double (u = 638.99999999 rounded to float was 639, one past the last 2x2 cell: AddressSanitizer
// found it) and clamped as well.
struct Cell {
  Cell(const cv::Mat& samples, double u, double v)
      : u0(std::min(static_cast<int>(u), samples.cols - 2)),
        v0(std::min(static_cast<int>(v), samples.rows - 2)),
        right(u - u0 >= 0.5),
        down(v - v0 >= 0.5),
        a(static_cast<float>(u - u0)),
        b(static_cast<float>(v - v0)),
        r0(samples.ptr<float>(v0) + 4 * u0),
        r1(samples.ptr<float>(v0 + 1) + 4 * u0) {}
  int ui() const { return u0 + right; }  //!< the nearest pixel
  int vi() const { return v0 + down; }
  /** (grey, gx, gy, 0), bilinear at (u, v) */
  Eigen::Array4f bilinear() const {
    using A = Eigen::Map<const Eigen::Array4f>;
    return (1 - b) * ((1 - a) * A(r0) + a * A(r0 + 4)) + b * ((1 - a) * A(r1) + a * A(r1 + 4));
  }
  int u0, v0;
  bool right, down;
  float a, b;
  const float *r0, *r1;
};

// Jacobian of a residual whose derivative with respect to the moved point P is g, for a left
// perturbation exp(delta) T with delta = (translation, rotation). (`inline` here and on
// toMiddleRow: GCC called both out of line, 6 % of a fr1/rpy run.)
inline Vector6d jacobian(const Eigen::Vector3d& P, const Eigen::Vector3d& g) {
  Vector6d J;
  J << g, P.cross(g);
  return J;
}

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

// Sums w [J r]^T [J r] over the residuals of an evaluation: the lower triangle of a 7x7 whose
// top-left 6x6 is H and whose last row is b^T. Each residual's sqrt(w) [J r] is kept in float in
// blocks of kBlock, whose 28 products are summed over 8 independent float lanes (the loops the
// compiler turns into SIMD) and added to the double sums block by block. (Floats hold the
// products of depths down to micrometres; below, the sums overflow, and refineDense() answers
// not ok. Checking each residual's range to sum those in double cost 15 % of the refinement.)
class Accumulator {
 public:
  void add(const Vector6d& J, double r, double w) {
    const float s = static_cast<float>(std::sqrt(w));
    for (int i = 0; i < 6; ++i) m_a[i][m_n] = s * static_cast<float>(J[i]);
    m_a[6][m_n] = s * static_cast<float>(r);
    if (++m_n == kBlock) flush();
  }
  void flush() {
    for (int i = 0; i < 7; ++i)
      for (int k = m_n; k < (m_n + kLanes - 1) / kLanes * kLanes; ++k) m_a[i][k] = 0;
    for (int i = 0; i < 7; ++i)
      for (int j = 0; j <= i; ++j) {
        float lanes[kLanes] = {};
        for (int k = 0; k < m_n; k += kLanes)
          for (int l = 0; l < kLanes; ++l) lanes[l] += m_a[i][k + l] * m_a[j][k + l];
        double sum = 0;
        for (float x : lanes) sum += x;
        S(i, j) += sum;
      }
    m_n = 0;
  }
  Eigen::Matrix<double, 7, 7> S = Eigen::Matrix<double, 7, 7>::Zero();

 private:
  static constexpr int kBlock = 256, kLanes = 8;
  alignas(16) float m_a[7][kBlock];
  int m_n = 0;
};

}  // namespace

LevelSolver::LevelSolver(const DenseLevel& cur, const DenseLevel& ref, const DenseParams& p,
                         int stride, const ReadoutMotion& cur_readout,
                         const ReadoutMotion& ref_readout)
    : m_ref(ref),
      m_p(p),
      m_points(currentPoints(cur, stride, cur_readout)),
      m_ref_readout(ref_readout),
      m_geometric_points(static_cast<std::size_t>(std::count_if(
          m_points.begin(), m_points.end(), [](const auto& q) { return q.geometric; }))),
      m_geometric_weight(p.geometric_weight * stride * stride),
      m_skip_untextured(!ref.textured.empty() && p.min_gradient >= ref.textured_gradient) {}

// The reference's tangent plane at pixel (ui, vi) of depth zr, and P's distance from it; none
// where the depth or the normal is unknown.
inline std::optional<LevelSolver::TangentPlane> LevelSolver::tangentPlane(const Eigen::Vector3d& P,
                                                                          int ui, int vi,
                                                                          float zr) const {
  if (!std::isfinite(zr)) return std::nullopt;
  const cv::Vec3f nv = m_ref.normals.at<cv::Vec3f>(vi, ui);
  if (!std::isfinite(nv[0])) return std::nullopt;
  const Eigen::Vector3d n(nv[0], nv[1], nv[2]);
  return TangentPlane{n, n.dot(P - m_ref.cam.backProject(ui, vi, zr))};
}

// Calls f(P, 1 / P.z, cell, z_ref, grey, geometric) for every `step`-th current point that T moves
// into the reference image without landing in front of or behind the reference depth (occlusion
// gate; unknown reference depth passes, for the photometric term).
template <class F>
void LevelSolver::forEachPair(const Eigen::Isometry3d& T, F f, std::size_t step) const {
  const auto& c = m_ref.cam;
  for (std::size_t i = 0; i < m_points.size(); i += step) {
    const CurrentPoint& pt = m_points[i];
    const Eigen::Vector3d P = T * pt.at_reference_rows;
    if (P.z() <= 0) continue;
    const double iz = 1 / P.z();
    const double u = c.fx * P.x() * iz + c.cx, v = c.fy * P.y() * iz + c.cy;
    if (!(u >= 0 && v >= 0 && u < c.width - 1 && v < c.height - 1)) continue;
    const Cell cell(m_ref.samples, u, v);
    const float zr = m_ref.depth.at<float>(cell.vi(), cell.ui());
    if (std::abs(zr - P.z()) > m_p.max_depth_difference) continue;  // false for NaN
    f(P, iz, cell, zr, pt.grey, pt.geometric);
  }
}

// Undoes the reference's rolling shutter for motions near T: each point is moved by the
// reference's motion between the frame time and the row T maps it to, taken into the current
// frame. Fixed for a level's iterations (a step moves the row by about a pixel at the finest
// level, the correction by that share of one readout's motion).
void LevelSolver::startAt(const Eigen::Isometry3d& T) {
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
NoiseScales LevelSolver::noiseScales(const Eigen::Isometry3d& T) const {
  std::vector<float> photo, depth;  // |residual|; |point-to-plane residual| / z^2 / sqrt(2)
  const bool measure_depth = m_p.clean_depth_fraction > 0 && m_p.geometric_weight > 0;
  const std::size_t step = m_geometric_points >= kSampledLevel ? kScaleSampleStep : 1;
  photo.reserve(m_points.size() / step + 1);
  if (measure_depth) depth.reserve(m_geometric_points / step + 1);
  forEachPair(
      T,
      [&](const Eigen::Vector3d& P, double iz, const Cell& cell, float zr, float grey,
          bool geometric) {
        photo.push_back(std::abs(cell.bilinear()[0] - grey));
        if (!measure_depth || !geometric) return;
        if (const auto plane = tangentPlane(P, cell.ui(), cell.vi(), zr))
          depth.push_back(static_cast<float>(std::abs(plane->distance) * iz * iz / std::sqrt(2.0)));
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
NormalEquations LevelSolver::normalEquations(const Eigen::Isometry3d& T,
                                             const NoiseScales& scales) const {
  NormalEquations n;
  const double k = m_p.huber, cap = 2.5 * k * k;  // Huber cost at e = 3k
  Accumulator sums;
  // inv_sigma: 1 / the residual's noise sigma
  auto add = [&](const Vector6d& J, double r, double inv_sigma, double weight) {
    const double e = std::abs(r) * inv_sigma;
    const double w = weight * (e <= k ? 1 : k / e) * inv_sigma * inv_sigma;
    sums.add(J, r, w);
    const double rho = e <= k ? 0.5 * e * e : k * (e - 0.5 * k);
    n.cost += weight * rho;
    n.score += std::min(rho, cap);
  };
  const auto& c = m_ref.cam;
  const double inv_photo_sigma = 1 / scales.photometric;
  // 1 / the sigma of a point-to-plane residual at 1 m (below)
  const double inv_depth_sigma = 1 / (std::sqrt(2.0) * scales.depth_noise);
  forEachPair(T, [&](const Eigen::Vector3d& P, double iz, const Cell& cell, float zr, float grey,
                     bool geometric) {
    if (m_p.photometric_weight > 0 &&
        (!m_skip_untextured || m_ref.textured.at<uchar>(cell.v0, cell.u0))) {
      const Eigen::Array4f at = cell.bilinear();
      const double gx = at[1], gy = at[2];
      if (gx * gx + gy * gy >= m_p.min_gradient * m_p.min_gradient) {
        const Eigen::Vector3d g(gx * c.fx * iz, gy * c.fy * iz,
                                -(gx * c.fx * P.x() + gy * c.fy * P.y()) * iz * iz);
        add(jacobian(P, g), at[0] - grey, inv_photo_sigma, m_p.photometric_weight);
        ++n.photometric;
        n.gradients.noalias() += Eigen::Vector2d(gx, gy) * Eigen::Vector2d(gx, gy).transpose();
      }
    }
    if (m_p.geometric_weight <= 0 || !geometric) return;
    const auto plane = tangentPlane(P, cell.ui(), cell.vi(), zr);
    if (!plane) return;
    // both depths are noisy: the sigma of the difference of two readings at about this depth
    const double inv_sigma = iz * iz * inv_depth_sigma;
    add(jacobian(P, plane->normal), plane->distance, inv_sigma, m_geometric_weight);
    ++n.geometric;
    n.normals.noalias() += plane->normal * plane->normal.transpose();
  });
  sums.flush();
  n.H = sums.S.topLeftCorner<6, 6>().selfadjointView<Eigen::Lower>();
  n.b = sums.S.block<1, 6>(6, 0).transpose();
  const std::size_t pairs = n.photometric + n.geometric;
  const std::size_t slots = (m_p.photometric_weight > 0 ? m_points.size() : 0) +
                            (m_p.geometric_weight > 0 ? m_geometric_points : 0);
  n.cost /= std::max<std::size_t>(1, pairs);
  n.score = slots ? (n.score + (slots - pairs) * cap) / slots : cap;
  return n;
}

}  // namespace hrgbd::dense
