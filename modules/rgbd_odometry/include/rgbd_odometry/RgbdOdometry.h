#pragma once
/** \file RgbdOdometry.h
 * Frame-to-frame RGB-D odometry (paper Algorithm 2): register each frame to the last registered
 * one and chain the motions, G_n = G_{n-1} T_{n,n-1} (eq. 8). */
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/poses/CPose3D.h>

#include <opencv2/rgbd.hpp>
#include <optional>
#include <string>

#include "rgbd_odometry/GeometricFeatures.h"
#include "rgbd_odometry/OdometryParams.h"

namespace hrgbd {

/** Outcome of one frame. Poses are of the colour camera's optical frame in the first frame's
 * optical frame (TUM convention). */
struct FrameResult {
  enum class Status {
    FirstFrame,         //!< the reference; pose = identity
    Ok,                 //!< registered
    BadInput,           //!< no colour / depth / intrinsics (see `detail`); pose predicted
    TooFewFeatures,     //!< too few features on the path used; pose predicted
    TooFewMatches,      //!< pose predicted
    DegenerateSamples,  //!< every 3-point sample degenerate; pose predicted
    TooFewInliers,      //!< pose predicted
    LargeResiduals,     //!< inlier noise scale implausible; pose predicted
    ImplausibleMotion,  //!< estimate beyond max_step_*; pose predicted
  };
  double t = 0;  //!< [s]
  mrpt::poses::CPose3D pose;
  Status status = Status::FirstFrame;
  std::string detail;                //!< human-readable reason when not Ok
  std::string path = "photometric";  //!< photometric|geometric|dense (peers)|none
  std::size_t orb_features = 0;      //!< ORB features with depth (what the switch counts)
  std::size_t features = 0, matches = 0, inliers = 0;  //!< on the path used
  double scale = 0;                                    //!< [m] estimator noise scale
  /** [m] the current frame's inlier features (optical frame), for display; empty on failure */
  std::vector<Eigen::Vector3f> inlier_points;
  // [ms] per stage
  double ms_prepare = 0, ms_features = 0, ms_matching = 0, ms_estimation = 0, ms_refine = 0,
         ms_total = 0;
  bool registered() const { return status == Status::Ok || status == Status::FirstFrame; }
};
const char* toString(FrameResult::Status s);

class RgbdOdometry {
 public:
  /** Takes `params` as they are: loading checked them (OdometryParams::validate() checks values
   * set in code). Every Method and FailurePolicy is available. */
  explicit RgbdOdometry(const OdometryParams& params);
  /** Registers one frame. Never throws for bad frames (they come back flagged). */
  FrameResult processObservation(const mrpt::obs::CObservation3DRangeScan& obs);
  /** Forgets everything: the next frame becomes the new origin. */
  void reset();
  const mrpt::poses::CPose3D& pose() const { return m_pose; }

 private:
  struct Keyframe {
    RgbdImage image;
    FeatureSet orb;
    std::optional<GeometricFeatures> geometric;  // computed when a frame first needs it
    mrpt::poses::CPose3D pose;
  };
  /** Matching and robust estimation of `cur` against the reference on one path. */
  struct Registration {
    FrameResult::Status status = FrameResult::Status::TooFewFeatures;
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    std::string detail;
  };
  Registration registerPhotometric(Keyframe& cur, FrameResult& r);
  Registration registerGeometric(Keyframe& cur, FrameResult& r);
  Registration registerPeer(const Keyframe& cur, FrameResult& r);
  const GeometricFeatures& geometricFeatures(Keyframe& k, FrameResult& r);
  FrameResult predict(FrameResult r, FrameResult::Status why, std::string detail);

  OdometryParams m_params;
  Method m_method;
  FailurePolicy m_policy;
  std::optional<Keyframe> m_ref;       // last registered frame
  cv::Ptr<cv::rgbd::Odometry> m_peer;  // OpenCV peer, made on its first frame (needs K)
  mrpt::poses::CPose3D m_pose;         // pose of the latest frame
  mrpt::poses::CPose3D m_velocity;     // last registered per-frame motion
};

}  // namespace hrgbd
