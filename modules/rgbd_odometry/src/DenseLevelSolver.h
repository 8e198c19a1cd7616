#pragma once
/** \file DenseLevelSolver.h (private to rgbd_odometry)
 * One pyramid level of the dense refinement: the current frame's points, and the noise scales and
 * Gauss-Newton system of their residuals against the reference at a pose. refineDense()
 * (DenseRefinement.cpp) runs the levels coarse to fine. */
#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "rgbd_odometry/DenseRefinement.h"

namespace hrgbd::dense {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

// The noise sigmas that normalise the residuals at one level.
struct NoiseScales {
  double photometric = 1;  //!< [grey levels]
  double depth_noise = 0;  //!< [1/m] depth sigma / z^2
};

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
  /** sum of g g^T over the photometric pairs' intensity gradients g [grey levels / px] */
  Eigen::Matrix2d gradients = Eigen::Matrix2d::Zero();
};

// The point of the current frame with its intensity; `geometric`: it has a point-to-plane term.
struct CurrentPoint {
  Eigen::Vector3d P;  //!< at the frame time
  /** P moved so that T maps it where the reference saw it: at the time of the reference row it
   * lands on (undoes the reference's rolling shutter; P for a global shutter) */
  Eigen::Vector3d at_reference_rows;
  float grey;
  bool geometric;
};

/** The residuals of one level's current points against its reference, at any pose. */
class LevelSolver {
 public:
  /** `stride`: the point-to-plane term on every stride-th row and column */
  LevelSolver(const DenseLevel& cur, const DenseLevel& ref, const DenseParams& p, int stride,
              const ReadoutMotion& cur_readout, const ReadoutMotion& ref_readout);
  double fx() const { return m_ref.cam.fx; }  //!< [px] of the level
  /** Undoes the reference's rolling shutter for motions near T (fixed for a level's iterations). */
  void startAt(const Eigen::Isometry3d& T);
  /** The noise scales at T (1.4826 x the median absolute residual of each term). */
  NoiseScales noiseScales(const Eigen::Isometry3d& T) const;
  /** The normal equations of the Huber-weighted, noise-normalised residuals at T. */
  NormalEquations normalEquations(const Eigen::Isometry3d& T, const NoiseScales& scales) const;

 private:
  struct TangentPlane {
    Eigen::Vector3d normal;  //!< the reference's, unit
    double distance;         //!< [m] of the point from the plane, signed
  };
  std::optional<TangentPlane> tangentPlane(const Eigen::Vector3d& P, int ui, int vi,
                                           float zr) const;
  template <class F>
  void forEachPair(const Eigen::Isometry3d& T, F f, std::size_t step = 1) const;

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

}  // namespace hrgbd::dense
