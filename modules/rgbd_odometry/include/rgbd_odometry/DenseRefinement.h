#pragma once
/** \file DenseRefinement.h
 * Dense refinement of a rigid motion that fuses colour and depth (beyond the paper; its future
 * work): the sparse estimate is the start, and Gauss-Newton on SE(3) minimises over an image
 * pyramid a joint cost of photometric residuals (intensity after warping) and point-to-plane
 * residuals (depth), each normalised by its noise and robustly weighted (Huber).
 *
 * Written here because neither MRPT nor OpenCV offers it as a refinement of a given estimate with
 * a depth-noise model: cv::rgbd::RgbdICPOdometry is a complete odometry whose cost treats every
 * depth alike. Its ideas are those of DVO (Kerl et al.) and KinectFusion's projective ICP. */
#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "rgbd_core/Params.h"
#include "rgbd_core/RgbdImage.h"

namespace hrgbd {

/** Parameters of the dense refinement. INI section [Dense]. */
struct DenseParams : public Params<DenseParams> {
  bool enabled = true;   //!< refine every sparse estimate (false: the paper's sparse result)
  int levels = 4;        //!< pyramid levels, each half the size of the one below
  int finest_level = 1;  //!< 0 = full resolution; 1 = half (faster, nearly as accurate)
  int iterations = 10;   //!< most Gauss-Newton steps per level
  /** [px] a Gauss-Newton step that moves the image by less than this (rotation, and translation
   * at 1 m) at its level is taken without an evaluation and ends the level. 0.05 px is 0.2 mm and
   * 0.011 deg at the half-size level of a Kinect (the default finest level), twice that one level
   * coarser. It was a fixed 0.1 mm / 0.006 deg at every level, and half of the finest level's
   * evaluations were of steps under 0.3 mm: 0.05 px took the refinement's median on fr1/rpy from
   * 13.5 to 10.9 ms (0.80) with the same ATE on the six real folders and the simulated suite. */
  double converged_px = 0.05;
  double photometric_weight = 1;  //!< weight of the intensity term (0 = off)
  double geometric_weight = 1;    //!< weight of the point-to-plane term (0 = off)
  /** the point-to-plane term at the finest level on every n-th row and column (weighted n^2 to
   * keep the balance of the terms); 1 = every pixel */
  int geometric_stride = 2;
  /** [1/m] Kinect depth noise sigma = depth_noise * z^2 (Khoshelham & Elberink 2012: ~1.4e-3). */
  double depth_noise = 0.0015;
  /** When the point-to-plane residuals' scale at a level's start (from at least 100 pairs, sampled
   * on large levels) is below this share of depth_noise, the depth is far cleaner than a Kinect's
   * (a render) and that scale replaces the model's (never below 1/50 of it), so that the exact term
   * is not outweighed by the intensity term and its biases at depth edges. At the finest level real
   * Kinect frames measured 0.38-1.6 of the model (other sensors: not measured). 0 = always the
   * model. */
  double clean_depth_fraction = 0.25;
  double max_depth = 5.0;  //!< [m] farther depth is not used
  /** [m] a warped point this far from the reference depth is occluded or disoccluded: left out */
  double max_depth_difference = 0.07;
  double min_gradient = 4;         //!< [grey levels/px] weaker intensity gradients are left out
  double huber = 1.345;            //!< Huber threshold on residuals divided by their sigma
  int min_pixels = 500;            //!< [count] fewer pairs at the finest level: not refined
  double max_correction = 0.2;     //!< [m] a larger change of the start is not trusted
  double max_correction_deg = 10;  //!< [deg] ... nor a larger rotation change
  /** What the data constrain, checked on every refined motion: either its texture or its
   * structure must pin down all six directions, else the frame is flagged `degenerate` (whatever
   * the sparse fit said). Texture does with at least min_texture_pairs intensity pairs at the
   * finest level whose gradients g point in two directions: the smaller eigenvalue of the sum of
   * g g^T at least min_texture_isotropy times the larger. Structure does with surfaces facing three
   * directions: the smallest eigenvalue of the mean n n^T of the paired normals at the coarsest
   * level (where depth noise moves them least) at least min_normal_spread. Measured on every frame
   * of the six shared real folders: at least 2,089 pairs and isotropy 0.16 (fr1/rpy) to 0.98; the
   * simulator's degenerate scenes: a plain wall 0 pairs, with colour noise 6 grey levels at most
   * 540, a plain corridor at most 296; a wall with stripes 24,000-38,000 pairs of isotropy at most
   * 0.019; normal spread of the walls (near and far) 0.013-0.049, the corridor 0.005, the real
   * plain structure (fr3) at least 0.057 (frames that pass by texture as well). */
  int min_texture_pairs = 1000;
  double min_texture_isotropy = 0.05;  //!< see min_texture_pairs
  double min_normal_spread = 0.055;    //!< see min_texture_pairs
  /** A frame registered by the refinement alone (no sparse estimate), or by the refinement from
   * the motion prediction where that fitted better than the sparse fit's, must explain the
   * reference's depth: at least this share of its points (every 2nd pixel) that the motion moves
   * onto known reference depth must agree with it within 3 sigma of the depth-noise model of two
   * readings (DepthAgreement.h). Where the prediction's does not, the sparse fit's refinement is
   * taken if it does; otherwise the frame is flagged. Measured on correct motions: real frames
   * 0.48-0.99 (fr1/rpy's fast rotation lowest; 0.63-0.98 on the 18 registered by the refinement
   * alone, 0.50-0.93 on the 20 where the prediction won), simulated 0.69-0.92; on wrong ones that
   * the refinement from the prediction had accepted (frames out of order, 0.1-1.3 m apart)
   * 0.00-0.32, and 0.39 on fr1/rpy with its depth scaled by 1.1. Fewer than min_pixels points on
   * known reference depth (a keyframe without depth): not judged. 0 = no check. */
  double min_depth_agreement = 0.45;
  /** The refinement of a sparse fit must explain some of the reference's depth as well: at least
   * this share of its points (every 4th pixel), as min_depth_agreement. Frames of noise (random
   * colour and depth), whose features match by chance, agreed at 0.024 at most; the frames of
   * the six shared real folders at 0.48 (fr1/rpy) or more. 0 = no check. */
  double min_depth_agreement_sparse = 0.2;
  /** [ms] readout time of a rolling shutter, first row to last, of colour and depth alike; each
   * row's points are moved to the frame time (the middle row) with the camera's velocity.
   * 0 = a global shutter, unless the input knows its camera's (the playback then takes that:
   * [TumSource] rolling_shutter_ms). */
  double rolling_shutter_ms = 0;

  template <class P, class V>
  static void declare(P& p, V& v) {
    HRGBD_PARAM(enabled, "refine every sparse estimate densely (colour + depth)");
    HRGBD_PARAM(levels, "pyramid levels, each half the size", Range::closed(1, 8));
    HRGBD_PARAM(finest_level, "0 = full resolution, 1 = half, ...", Range::closed(0, 7));
    HRGBD_PARAM(iterations, "most Gauss-Newton steps per level", Range::atLeast(1));
    HRGBD_PARAM(converged_px, "[px] a smaller step at its level ends the level",
                Range::openClosed(0, 1));
    HRGBD_PARAM(photometric_weight, "weight of the intensity term (0 = off)", Range::atLeast(0));
    HRGBD_PARAM(geometric_weight, "weight of the point-to-plane term (0 = off)", Range::atLeast(0));
    HRGBD_PARAM(geometric_stride, "point-to-plane term on every n-th row and column (finest level)",
                Range::closed(1, 8));
    HRGBD_PARAM(depth_noise, "[1/m] depth sigma = depth_noise z^2", Range::above(0));
    HRGBD_PARAM(clean_depth_fraction,
                "measured depth scale below this share of the model's replaces it (0 = never)",
                Range::closed(0, 1));
    HRGBD_PARAM(max_depth, "[m] farther depth is not used", Range::above(0));
    HRGBD_PARAM(max_depth_difference, "[m] occlusion gate between warped and reference depth",
                Range::above(0));
    HRGBD_PARAM(min_gradient, "[grey levels/px] weaker gradients are left out", Range::atLeast(0));
    HRGBD_PARAM(huber, "Huber threshold on normalised residuals", Range::above(0));
    HRGBD_PARAM(min_pixels, "[count] fewer pairs at the finest level: not refined",
                Range::atLeast(6));
    HRGBD_PARAM(max_correction, "[m] larger change of the sparse estimate: not trusted",
                Range::above(0));
    HRGBD_PARAM(max_correction_deg, "[deg] larger rotation change: not trusted",
                Range::openClosed(0, 180));
    HRGBD_PARAM(min_texture_pairs, "[count] fewer intensity pairs: texture constrains nothing",
                Range::atLeast(0));
    HRGBD_PARAM(min_texture_isotropy, "texture in two directions: gradient tensor's eigen ratio",
                Range::closed(0, 1));
    HRGBD_PARAM(min_normal_spread, "structure: smallest eigenvalue of the mean n n^T (coarsest)",
                Range::closed(0, 1.0 / 3));
    HRGBD_PARAM(min_depth_agreement,
                "refinement alone / from the prediction: share of points agreeing with the depth",
                Range::closed(0, 1));
    HRGBD_PARAM(min_depth_agreement_sparse,
                "refinement of a sparse fit: share of points agreeing with the depth",
                Range::closed(0, 1));
    HRGBD_PARAM(rolling_shutter_ms, "[ms] rolling-shutter readout, first to last row (0 = global)",
                Range::atLeast(0));
  }
  void checkTogether(const std::string& section) const;
};

/** One pyramid level: intensity, depth (NaN = unknown, never blended into known depth), the
 * intensity gradients, the normals of the depth (NaN where unknown) and the textured cells. */
struct DenseLevel {
  PinholeCamera cam;
  cv::Mat grey;     //!< CV_32F, grey levels
  cv::Mat depth;    //!< CV_32F, metres, NaN = unknown
  cv::Mat normals;  //!< CV_32FC3, unit, towards the camera; NaN = unknown
  /** CV_8U, non-zero where a corner of the 2x2 cell at (u, v)..(u + 1, v + 1) has a gradient
   * of at least `textured_gradient` (less 0.01 % for rounding): elsewhere no bilinear sample of
   * the gradient reaches it, and the refinement skips the cell (a shortcut, the same result) */
  cv::Mat textured;
  double textured_gradient = 0;  //!< [grey levels/px] the min_gradient it was made with
  /** [1/m] packLevels() stored grey as CV_16F and depth as CV_16U in these units (0 = unknown);
   * 0 = not packed */
  double packed_depth_units = 0;
  /** CV_32FC4, (grey, gx, gy, 0) of each pixel side by side, gx and gy its intensity gradients
   * [grey levels per pixel]: the refinement reads a reference's 2x2 cell as 4 vectors of 16
   * bytes, not 12 scattered floats (the depth stays apart: most pairs read only the depth, from
   * the smaller image) */
  cv::Mat samples;
};

/** Levels from the finest used (index 0) to the coarsest. */
struct DensePyramid {
  std::vector<DenseLevel> levels;
};

/** A camera's motion during one readout of a rolling shutter, first row to last: translation
 * [m] and rotation vector [rad] in the camera frame. Zero: a global shutter or unknown. */
using ReadoutMotion = Eigen::Matrix<double, 6, 1>;

/** The pyramid of a frame, each level with its derivatives (addDerivatives()) unless
 * `derivatives` is false: only a reference needs them, and most tracked frames never become one. */
DensePyramid buildDensePyramid(const RgbdImage& image, const DenseParams& params,
                               bool derivatives = true);

/** Adds the level's gradients, textured cells and normals, made from its grey and depth. Only a
 * reference needs them: a pyramid stored for later use may drop them (78 % of its memory) and
 * have them added again when it becomes a reference. */
void addDerivatives(DenseLevel& level, const DenseParams& params);
/** Releases what addDerivatives() adds: the level keeps its camera, grey and depth. */
void dropDerivatives(DenseLevel& level);
/** Whether the level has what addDerivatives() adds. */
bool hasDerivatives(const DenseLevel& level);
/** addDerivatives() on every level of `pyramid` that has none. */
void addDerivatives(DensePyramid& pyramid, const DenseParams& params);
/** dropDerivatives() on every level. */
void dropDerivatives(DensePyramid& pyramid);
/** Stores a pyramid kept for later use in half the memory: every level's derivatives dropped, its
 * grey in half precision (at most 1/16 grey level off) and its depth in 16-bit units, the
 * level's farthest known depth being 65534 of them (at most 1/131068 of it off: 0.04 mm for 5
 * m; unknown as 0). refineDense() refuses it until unpackLevels(). */
void packLevels(DensePyramid& pyramid);
/** Restores the grey and depth of packLevels() (CV_32F, unknown depth NaN); its derivatives are
 * then made again by addDerivatives(). Levels not packed are left as they are. */
void unpackLevels(DensePyramid& pyramid);

/** Result of refineDense(). */
struct DenseResult {
  bool ok = false;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();     //!< maps current points into reference
  std::size_t photometric_pairs = 0, geometric_pairs = 0;  //!< at the finest level
  /** Gauss-Newton steps evaluated, all levels (taken or refused as uphill; a converged step is
   * taken without an evaluation and not counted) */
  int iterations = 0;
  std::size_t start = 0;  //!< index of the start that fitted best
  /** when another start fitted best: where starts[0] was refined to at the finest level */
  std::optional<Eigen::Isometry3d> first_start_refined;
  /** smallest eigenvalue of the mean n n^T of the paired reference normals at the coarsest level
   * (where the depth noise moves them least): near 0 when the surfaces seen do not face three
   * independent directions (a plane, a corridor) */
  double normal_spread = 0;
  /** smaller over larger eigenvalue of the sum of g g^T over the photometric pairs' intensity
   * gradients g: near 0 when the texture varies in one direction only (stripes, an edge) */
  double texture_isotropy = 0;
  std::string detail;  //!< why, when not ok
};

/** Refines a motion (current -> reference) by minimising the joint cost, coarse to fine. Each of
 * `starts` is refined level by level and the one that fits best at the finest level wins (most
 * points paired with small residuals): a wrong sparse estimate loses against the motion
 * prediction. A start that a coarser level brings next to an earlier one (within two converged
 * steps, converged_px) is dropped there: the earlier one goes on alone. Not ok (T = starts[0]) when
 * the winner has fewer than min_pixels pairs in all, or when the reference has no derivatives. */
DenseResult refineDense(const DensePyramid& cur, const DensePyramid& ref,
                        const std::vector<Eigen::Isometry3d>& starts, const DenseParams& params,
                        const ReadoutMotion& cur_readout = ReadoutMotion::Zero(),
                        const ReadoutMotion& ref_readout = ReadoutMotion::Zero());

}  // namespace hrgbd
