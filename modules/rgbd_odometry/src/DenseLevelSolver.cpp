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
// interleaved (grey, gx, gy, 0) samples, and its pixel nearest to (u, v). (u, v) are the values
// the bounds were checked on (a double rounded to float after its check was 639 for 638.99999999,
// one past the last 2x2 cell: AddressSanitizer found it); the cell is clamped as well.
struct Cell {
  Cell(const cv::Mat& samples, float u, float v)
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

using Vector6f = Eigen::Matrix<float, 6, 1>;

// Jacobian of a residual whose derivative with respect to the moved point P is g, for a left
// perturbation exp(delta) T with delta = (translation, rotation). (`inline` here and on
// toMiddleRow: GCC called both out of line, 6 % of a fr1/rpy run.)
// (Written out: Eigen's packet copy of g into J loads 4 floats of a 3-float vector.)
inline Vector6f jacobian(const Eigen::Vector3f& P, const Eigen::Vector3f& g) {
  Vector6f J;
  J << g.x(), g.y(), g.z(), P.y() * g.z() - P.z() * g.y(), P.z() * g.x() - P.x() * g.z(),
      P.x() * g.y() - P.y() * g.x();
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
CurrentPoints currentPoints(const DenseLevel& c, int stride, const ReadoutMotion& readout) {
  CurrentPoints pts;
  const bool rolling = !readout.isZero();
  for (int v = 0; v < c.depth.rows; ++v) {
    const double s = rowFraction(v, c.depth.rows);
    for (int u = 0; u < c.depth.cols; ++u) {
      const float z = c.depth.at<float>(v, u);
      if (!std::isfinite(z)) continue;
      const Eigen::Vector3d P = c.cam.backProject(u, v, z);
      pts.P.push_back(rolling ? toMiddleRow(P, s, readout) : P);
      pts.grey.push_back(c.grey.at<float>(v, u));
      pts.geometric.push_back(u % stride == 0 && v % stride == 0);
    }
  }
  for (const auto& P : pts.P) {
    pts.x.push_back(static_cast<float>(P.x()));
    pts.y.push_back(static_cast<float>(P.y()));
    pts.z.push_back(static_cast<float>(P.z()));
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
  void add(const Vector6f& J, float r, float w) {
    const float s = std::sqrt(w);
    for (int i = 0; i < 6; ++i) m_a[i][m_n] = s * J[i];
    m_a[6][m_n] = s * r;
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
      m_geometric_points(static_cast<std::size_t>(
          std::count(m_points.geometric.begin(), m_points.geometric.end(), 1))),
      m_geometric_weight(p.geometric_weight * stride * stride),
      m_skip_untextured(!ref.textured.empty() && p.min_gradient >= ref.textured_gradient) {}

// The reference's tangent plane at pixel (ui, vi) of depth zr, and P's distance from it; none
// where the depth or the normal is unknown.
inline std::optional<LevelSolver::TangentPlane> LevelSolver::tangentPlane(const Eigen::Vector3f& P,
                                                                          int ui, int vi,
                                                                          float zr) const {
  if (!std::isfinite(zr)) return std::nullopt;
  const cv::Vec3f nv = m_ref.normals.at<cv::Vec3f>(vi, ui);
  if (!std::isfinite(nv[0])) return std::nullopt;
  const Eigen::Vector3f n(nv[0], nv[1], nv[2]);
  const auto& c = m_ref.cam;
  const Eigen::Vector3f Q(static_cast<float>((ui - c.cx) / c.fx) * zr,
                          static_cast<float>((vi - c.cy) / c.fy) * zr, zr);
  return TangentPlane{n, n.dot(P - Q)};
}

// Calls f(P, 1 / P.z, cell, z_ref, grey, geometric) for every `step`-th current point that T moves
// into the reference image without landing in front of or behind the reference depth (occlusion
// gate; unknown reference depth passes, for the photometric term). In float, a block of points at
// a time: first their transform and projection (loops the compiler vectorises; the same pairs as
// in double to a thousandth of a pixel), then the gates and f, one point at a time. (In double,
// one point at a time: the refinement took 1.X times as long; measured in doc/measurements.md.)
template <class F>
void LevelSolver::forEachPair(const Eigen::Isometry3d& T, F f, std::size_t step) const {
  const auto& c = m_ref.cam;
  const Eigen::Matrix<float, 3, 4> M = T.matrix().topRows<3>().cast<float>();
  const float fx = static_cast<float>(c.fx), fy = static_cast<float>(c.fy);
  const float cx = static_cast<float>(c.cx), cy = static_cast<float>(c.cy);
  const float umax = static_cast<float>(c.width - 1), vmax = static_cast<float>(c.height - 1);
  const float max_gap = static_cast<float>(m_p.max_depth_difference);
  constexpr std::size_t kBlock = 256;
  alignas(32) float X[kBlock], Y[kBlock], Z[kBlock], U[kBlock], V[kBlock];
  const float *px = m_points.x.data(), *py = m_points.y.data(), *pz = m_points.z.data();
  const std::size_t n = m_points.size();
  std::vector<float> gx, gy, gz;  // the step's points, contiguous
  if (step > 1) {
    for (std::size_t i = 0; i < n; i += step)
      gx.push_back(px[i]), gy.push_back(py[i]), gz.push_back(pz[i]);
    px = gx.data(), py = gy.data(), pz = gz.data();
  }
  const std::size_t count = step > 1 ? gx.size() : n;
  for (std::size_t b = 0; b < count; b += kBlock) {
    const std::size_t m = std::min(kBlock, count - b);
    for (std::size_t k = 0; k < m; ++k) {
      const float x = px[b + k], y = py[b + k], z = pz[b + k];
      X[k] = M(0, 0) * x + M(0, 1) * y + M(0, 2) * z + M(0, 3);
      Y[k] = M(1, 0) * x + M(1, 1) * y + M(1, 2) * z + M(1, 3);
      Z[k] = M(2, 0) * x + M(2, 1) * y + M(2, 2) * z + M(2, 3);
      U[k] = fx * X[k] / Z[k] + cx;
      V[k] = fy * Y[k] / Z[k] + cy;
    }
    for (std::size_t k = 0; k < m; ++k) {
      if (!(Z[k] > 0)) continue;
      const float u = U[k], v = V[k];
      if (!(u >= 0 && v >= 0 && u < umax && v < vmax)) continue;
      const Cell cell(m_ref.samples, u, v);
      const float zr = m_ref.depth.at<float>(cell.vi(), cell.ui());
      if (std::abs(zr - Z[k]) > max_gap) continue;  // false for NaN
      const std::size_t i = (b + k) * step;
      f(Eigen::Vector3f(X[k], Y[k], Z[k]), 1 / Z[k], cell, zr, m_points.grey[i],
        m_points.geometric[i] != 0);
    }
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
  for (std::size_t i = 0; i < m_points.size(); ++i) {
    const Eigen::Vector3d& P = m_points.P[i];
    const Eigen::Vector3d X = T * P;
    // behind the reference: never paired, but no other start's correction
    const Eigen::Vector3d A =
        X.z() <= 0
            ? P
            : Eigen::Vector3d(
                  P - Rt * (toMiddleRow(X, rowFraction(c.fy * X.y() / X.z() + c.cy, c.height),
                                        m_ref_readout) -
                            X));
    m_points.x[i] = static_cast<float>(A.x());
    m_points.y[i] = static_cast<float>(A.y());
    m_points.z[i] = static_cast<float>(A.z());
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
      [&](const Eigen::Vector3f& P, float iz, const Cell& cell, float zr, float grey,
          bool geometric) {
        photo.push_back(std::abs(cell.bilinear()[0] - grey));
        if (!measure_depth || !geometric) return;
        if (const auto plane = tangentPlane(P, cell.ui(), cell.vi(), zr))
          depth.push_back(std::abs(plane->distance) * iz * iz / std::sqrt(2.0f));
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
  const float k = static_cast<float>(m_p.huber), cap = 2.5f * k * k;  // Huber cost at e = 3k
  Accumulator sums;
  // inv_sigma: 1 / the residual's noise sigma; costs summed in double
  auto add = [&](const Vector6f& J, float r, float inv_sigma, float weight) {
    const float e = std::abs(r) * inv_sigma;
    const float w = weight * (e <= k ? 1 : k / e) * inv_sigma * inv_sigma;
    sums.add(J, r, w);
    const float rho = e <= k ? 0.5f * e * e : k * (e - 0.5f * k);
    n.cost += weight * rho;
    n.score += std::min(rho, cap);
  };
  const float fx = static_cast<float>(m_ref.cam.fx), fy = static_cast<float>(m_ref.cam.fy);
  const float inv_photo_sigma = static_cast<float>(1 / scales.photometric);
  // 1 / the sigma of a point-to-plane residual at 1 m (below)
  const float inv_depth_sigma = static_cast<float>(1 / (std::sqrt(2.0) * scales.depth_noise));
  const float photometric_weight = static_cast<float>(m_p.photometric_weight);
  const float geometric_weight = static_cast<float>(m_geometric_weight);
  const float min_gradient2 = static_cast<float>(m_p.min_gradient * m_p.min_gradient);
  Eigen::Matrix3f normals = Eigen::Matrix3f::Zero();
  float gxx = 0, gxy = 0, gyy = 0;
  forEachPair(T, [&](const Eigen::Vector3f& P, float iz, const Cell& cell, float zr, float grey,
                     bool geometric) {
    if (photometric_weight > 0 &&
        (!m_skip_untextured || m_ref.textured.at<uchar>(cell.v0, cell.u0))) {
      const Eigen::Array4f at = cell.bilinear();
      const float gx = at[1] * fx, gy = at[2] * fy;
      if (at[1] * at[1] + at[2] * at[2] >= min_gradient2) {
        const Eigen::Vector3f g(gx * iz, gy * iz, -(gx * P.x() + gy * P.y()) * iz * iz);
        add(jacobian(P, g), at[0] - grey, inv_photo_sigma, photometric_weight);
        ++n.photometric;
        gxx += at[1] * at[1], gxy += at[1] * at[2], gyy += at[2] * at[2];
      }
    }
    if (geometric_weight <= 0 || !geometric) return;
    const auto plane = tangentPlane(P, cell.ui(), cell.vi(), zr);
    if (!plane) return;
    // both depths are noisy: the sigma of the difference of two readings at about this depth
    const float inv_sigma = iz * iz * inv_depth_sigma;
    add(jacobian(P, plane->normal), plane->distance, inv_sigma, geometric_weight);
    ++n.geometric;
    normals.noalias() += plane->normal * plane->normal.transpose();
  });
  n.normals = normals.cast<double>();
  n.gradients << gxx, gxy, gxy, gyy;
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
