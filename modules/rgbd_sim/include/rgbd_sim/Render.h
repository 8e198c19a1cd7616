#pragma once
/** \file Render.h
 * Ideal (noise-free) ray-cast rendering of a Scene, and the Kinect-like sensor model applied to
 * it. Hand-written: no Debian library here renders depth with a Kinect noise model. */

#include <mrpt/poses/CPose3D.h>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "rgbd_core/Params.h"
#include "rgbd_core/PinholeCamera.h"
#include "rgbd_core/Trajectory.h"
#include "rgbd_sim/Scene.h"

namespace hrgbd::sim {

/** A noise-free render. */
struct IdealFrame {
  cv::Mat colour;     //!< CV_32FC3 linear RGB in [0, 1] (before exposure and noise)
  cv::Mat depth;      //!< CV_32FC1 [m] along the optical axis, 0 = no surface
  cv::Mat incidence;  //!< CV_32FC1 |cos| of the angle between ray and surface normal
};

/** Ray-casts `scene` from `pose` (optical frame in the world: z forward, x right, y down). With
 * `last_row_pose`, a rolling shutter: row v is seen from the pose interpolated between `pose`
 * (row 0) and `last_row_pose` (last row). */
IdealFrame renderIdeal(const Scene& scene, const mrpt::poses::CPose3D& pose,
                       const PinholeCamera& cam,
                       const std::optional<mrpt::poses::CPose3D>& last_row_pose = std::nullopt);

/** Kinect (structured light) parameters. INI section [Simulator] (merged into SimParams). */
struct KinectModel : public Params<KinectModel> {
  double baseline = 0.075;                   //!< [m] projector-camera baseline
  double disparity_step = 0.125;             //!< [px] disparity quantisation (1/8 px)
  double disparity_noise = 0.06;             //!< [px] per-pixel disparity noise (std)
  double disparity_noise_correlated = 0.08;  //!< [px] smooth noise field (std), ~16 px blobs
  /** [px] disparity comes from block matching over this window (9x9 or 9x7 on the Kinect,
   * Konolige & Mihelich's ROS kinect_calibration notes): the per-pixel noise is averaged over it
   * (neighbours share most of their window), so it is spatially correlated. 1 = none. */
  int correlation_window = 9;
  /** [px] fixed-pattern disparity error of the sensor unit (std): smooth over the image and the
   * same in every frame, the residual distortion Kinect calibrations find. 0.3 px is ~1 % of
   * the depth at 2 m; set with the realism check (doc/simulator.md). 0 = none. */
  double disparity_distortion = 0.3;
  /** [px] a farther surface this close to a nearer one takes the nearer one's depth (the block
   * matcher's window locks onto the foreground: objects look fatter). 0 = none. */
  int edge_fattening = 4;
  double min_depth = 0.5, max_depth = 4.5;  //!< [m] no depth outside
  double min_incidence = 0.2;               //!< |cos| below which (grazing) there is no depth
  double edge_dropout = 0.6;    //!< probability of no depth next to a depth discontinuity
  double flying_pixels = 0.15;  //!< probability of a mixed depth at a discontinuity
  double colour_noise = 2.5;    //!< [grey levels] colour noise (std)
  double exposure_ms = 12;      //!< [ms] exposure: motion blur along the image motion
  /** [ms] rolling shutter readout from the first to the last row (both cameras, synchronised as
   * in TUM fr3; ~a frame time at 30 Hz): rows see the scene at different times while the camera
   * moves. 0 = global shutter. */
  double rolling_shutter_ms = 30;
  double auto_exposure = 0.06;  //!< relative amplitude of slow gain changes

  template <class P, class V>
  static void declare(P& p, V& v) {
    const auto px5 = Range::closed(0, 5);
    HRGBD_PARAM(baseline, "[m] projector-camera baseline", Range::open(0, 1));
    HRGBD_PARAM(disparity_step, "[px] disparity quantisation (0 = not quantised)",
                Range::closed(0, 1));
    HRGBD_PARAM(disparity_noise, "[px] per-pixel disparity noise (std)", px5);
    HRGBD_PARAM(disparity_noise_correlated, "[px] smooth noise field (std)", px5);
    HRGBD_PARAM(correlation_window, "[px] block-matching window (1 = none)", Range::closed(1, 31));
    HRGBD_PARAM(disparity_distortion, "[px] fixed-pattern disparity error (std)", px5);
    HRGBD_PARAM(edge_fattening, "[px] foreground depth spreads this far", Range::closed(0, 15));
    HRGBD_PARAM(min_depth, "[m] no depth nearer", Range::above(0));
    HRGBD_PARAM(max_depth, "[m] no depth farther, > min_depth");
    HRGBD_PARAM(min_incidence, "|cos| of grazing incidence without depth", Range::closedOpen(0, 1));
    HRGBD_PARAM(edge_dropout, "probability of no depth at a discontinuity", Range::atLeast(0));
    HRGBD_PARAM(flying_pixels, "probability of a mixed depth at a discontinuity; sum <= 1",
                Range::atLeast(0));
    HRGBD_PARAM(colour_noise, "[grey levels] colour noise (std)", Range::closed(0, 50));
    HRGBD_PARAM(exposure_ms, "[ms] exposure (motion blur)", Range::closed(0, 100));
    HRGBD_PARAM(rolling_shutter_ms, "[ms] readout, first to last row (0 = global)",
                Range::closed(0, 100));
    HRGBD_PARAM(auto_exposure, "relative amplitude of slow gain changes", Range::closedOpen(0, 1));
  }
  /** max_depth > min_depth; edge_dropout + flying_pixels <= 1. */
  void checkTogether(const std::string& s) const;
};

/** One frame's inputs to applyKinectModel() besides the ideal render. */
struct SensorInputs {
  mrpt::poses::CPose3D pose;           //!< camera (optical frame in the world) at the frame time
  mrpt::poses::CPose3D previous_pose;  //!< camera `exposure_ms` earlier: sets the motion blur
  double gain = 1.0;                   //!< auto-exposure gain on the linear colour
  double depth_factor = 5000;          //!< [1/m] raw depth units per metre (TUM: 5000)
};

/** What the sensor delivers. */
struct SensorFrame {
  cv::Mat bgr;    //!< CV_8UC3 colour
  cv::Mat depth;  //!< CV_16UC1 depth in units of 1/depth_factor m, 0 = no depth
};

/** Applies the sensor model to `ideal`: disparity noise (smooth, fixed-pattern and windowed
 * per-pixel), edge fattening, missing and flying depth at discontinuities, disparity
 * quantisation; motion blur, gain, gamma and noise on the colour. Draws from `rng` in a fixed
 * order, so a seed gives the same frames. */
[[nodiscard]] SensorFrame applyKinectModel(const IdealFrame& ideal, const PinholeCamera& cam,
                                           const SensorInputs& inputs, const KinectModel& model,
                                           std::mt19937& rng);

}  // namespace hrgbd::sim
