// The dense refinement's driver: every start refined level by level, coarse to fine, with
// Gauss-Newton on SE(3) (each level's residuals: DenseLevelSolver.cpp), and the best at the finest
// level kept.
#include "rgbd_odometry/DenseRefinement.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "DenseLevelSolver.h"
#include "rgbd_core/PoseGap.h"

namespace hrgbd {
namespace {

using dense::LevelSolver;
using dense::NoiseScales;
using dense::NormalEquations;
using dense::Vector6d;

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

// Whether a step could be taken from these normal equations (what the scoring requires of a start).
bool solvable(const NormalEquations& n) { return n.H.allFinite() && n.b.allFinite(); }

// Whether two refinements of different starts have met at a level: within two converged steps
// there (`step`: converged_px / fx of the level; metres and radians together). On fr1/rpy 57 of
// the 70 frames with two starts ended within 0.5 mm and 0.03 deg; dropping the later start once a
// level brings it there took 12 % off the refinement's time over the sequence with the same ATE on
// every real folder and the simulated suite. (A fixed 0.5 mm is too tight once the coarser
// levels stop at their own precision: the starts were then both refined to the finest level.)
// The smallest eigenvalue of the mean n n^T of the paired normals, 0 without any.
double spread(const NormalEquations& n) {
  return n.geometric ? Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(n.normals / n.geometric)
                           .eigenvalues()(0)
                     : 0;
}

bool together(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, double step) {
  const PoseGap g = poseGap(a, b);
  return g.metres * g.metres + g.radians * g.radians < 4 * step * step;
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
  const auto packed = [](const DenseLevel& l) { return l.packed_depth_units > 0; };
  if (std::any_of(cur.levels.begin(), cur.levels.end(), packed) ||
      std::any_of(ref.levels.begin(), ref.levels.end(), packed)) {
    out.detail = "dense refinement: a pyramid is packed (unpackLevels)";
    return out;
  }
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
    double coarsest_spread = 0;      // spread() at the coarsest level
  };
  std::vector<Refined> refined;
  for (std::size_t i = 0; i < starts.size(); ++i)
    refined.push_back({i, starts[i], {}, {}, starts[i], 0});
  for (int l = static_cast<int>(solvers.size()) - 1; l >= 0; --l) {
    for (auto& r : refined) {
      if (l == 0) r.finest_start = r.T;
      r.n = solveLevel(solvers[l], r.T, p, out.iterations, r.scales);
      if (l + 1 == static_cast<int>(solvers.size())) r.coarsest_spread = spread(r.n);
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
  // the winner's score so far; none while infinite (scores are capped: a NaN never wins)
  double best = std::numeric_limits<double>::infinity();
  Eigen::Isometry3d T = starts.front();
  for (std::size_t i = 0; i < refined.size(); ++i) {
    const auto& [start, Ti, n0, scales, finest_start, coarsest_spread] = refined[i];
    NormalEquations n = n0;
    if (!solvable(n)) continue;  // no step could be taken there
    if (scales.depth_noise < depth_noise) {
      solvers.front().startAt(finest_start);  // this start's rolling-shutter correction
      n = solvers.front().normalEquations(Ti, {scales.photometric, depth_noise});
    }
    if (n.score < best) {
      best = n.score, T = Ti, out.start = start;
      out.photometric_pairs = n.photometric, out.geometric_pairs = n.geometric;
      const Eigen::Vector2d g =
          Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(n.gradients).eigenvalues();
      out.texture_isotropy = g(1) > 0 ? g(0) / g(1) : 0;
      out.normal_spread = coarsest_spread;
    }
  }
  if (std::isinf(best)) {
    out.detail = "dense refinement: its normal equations are not finite (depth out of range?)";
    return out;
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
  // the first start's own refinement when another won (the first is never dropped: it is earlier
  // than any start it could meet)
  if (out.start != 0 && refined.front().start == 0 && solvable(refined.front().n))
    out.first_start_refined = refined.front().T;
  return out;
}

}  // namespace hrgbd
