#pragma once
/** \file RgbdOdometry.h
 * The tracker (paper Algorithm 2): each frame is prepared, registered against the reference
 * (the last registered frame, or the keyframe with keyframe_max_translation > 0, or a flagged
 * frame taken after keyframe_after_failures) by a
 * Registration, checked for plausibility, and accepted, which
 * chains the motion, G_n = G_ref T (eq. 8), or flagged, which predicts the pose. After
 * keyframe_after_failures flagged frames in a row, a flagged frame becomes the keyframe at its
 * predicted pose, so that tracking resumes from what the camera sees now. */
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/poses/CPose3D.h>

#include <memory>
#include <optional>

#include "rgbd_odometry/FrameResult.h"
#include "rgbd_odometry/OdometryParams.h"
#include "rgbd_odometry/Registration.h"

namespace hrgbd {

class RgbdOdometry {
 public:
  /** The product's registration for `params.method` (hybrid, rgb_only, depth_only); throws
   * ConfigError for a baseline or peer method (made by rgbd_baselines, use the constructor
   * below). */
  explicit RgbdOdometry(const OdometryParams& params);
  /** Tracking with any registration; `params` gives the plausibility limits and the failure
   * policy. */
  RgbdOdometry(const OdometryParams& params, std::unique_ptr<Registration> registration);
  /** Registers one frame. Never throws for bad frames (they come back flagged). */
  FrameResult processObservation(const mrpt::obs::CObservation3DRangeScan& obs);
  /** Forgets everything: the next frame becomes the new origin. */
  void reset();
  const mrpt::poses::CPose3D& pose() const { return m_pose; }
  /** The reference frames are registered against (the keyframe), with its pose; nullptr before
   * the first frame or after reset(). */
  const Frame* keyframe() const { return m_ref ? &m_ref->frame : nullptr; }
  /** Moves the whole trajectory so far by `correction` (left-composed onto the keyframe's and the
   * latest pose): how a pose-graph optimisation re-anchors the tracker. */
  void correct(const mrpt::poses::CPose3D& correction);

 private:
  struct Reference {
    Frame frame;
    mrpt::poses::CPose3D pose;
  };
  FrameResult track(const mrpt::obs::CObservation3DRangeScan& obs);
  std::optional<std::string> implausible(const Eigen::Isometry3d& T) const;
  FrameResult predict(FrameResult r, FrameResult::Status why, std::string detail);
  /** predict(), and `frame` becomes the keyframe after keyframe_after_failures in a row. */
  FrameResult failed(Frame frame, FrameResult r, FrameResult::Status why, std::string detail);
  bool newKeyframe(const RegistrationResult& reg) const;
  /** Sets m_after_gap when the frame at `t` comes after a time gap (prediction_max_gap);
   * remembers `t`. */
  void noteTimeGap(double t);
  FrameResult accept(Frame frame, const mrpt::poses::CPose3D& pose, FrameResult r, bool keyframe);

  OdometryParams m_params;
  std::unique_ptr<Registration> m_registration;
  std::optional<Reference> m_ref;   // last registered frame, the keyframe, or a flagged one
  mrpt::poses::CPose3D m_pose;      // pose of the latest frame
  mrpt::poses::CPose3D m_velocity;  // last registered per-frame motion
  // m_velocity per second (translation, rotation vector), once measured: a rolling shutter's
  // skew is undone with it
  std::optional<Eigen::Matrix<double, 6, 1>> m_twist;
  bool m_previous_registered = false;
  int m_failures = 0;              // flagged frames since the last registered one or keyframe
  int m_flagged_run = 0;           // flagged frames since the last registered one
  std::optional<double> m_last_t;  // [s] the previous frame's time
  double m_mean_interval = 0;      // [s] running mean of the intervals between frames
  double m_interval = 0;           // [s] the latest interval (0: the first frame, or out of order)
  bool m_after_gap = false;        // no frame registered since a time gap: no prediction
};

}  // namespace hrgbd
