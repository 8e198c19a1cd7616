#pragma once
/** \file Registration.h
 * The seam between the tracker and the ways of registering two frames. A Registration
 * prepares each frame once (features it needs) and aligns a prepared frame with a prepared
 * reference. The paper's paths are PhotometricRegistration, GeometricRegistration and the
 * HybridRegistration policy over both; the baselines and peers (library rgbd_baselines) are
 * further implementations. */
#include <Eigen/Geometry>
#include <any>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "rgbd_core/RgbdImage.h"
#include "rgbd_odometry/DenseRefinement.h"
#include "rgbd_odometry/FrameResult.h"
#include "rgbd_odometry/GeometricFeatures.h"
#include "rgbd_odometry/OrbFeatures.h"

namespace hrgbd {

/** A frame prepared for registration, with the features computed for it so far (each
 * registration computes what it needs, once). */
struct Frame {
  RgbdImage image;
  std::optional<FeatureSet> orb;               //!< ORB features with depth (III-B)
  std::optional<GeometricFeatures> geometric;  //!< IS3D + SHOT (III-C to III-F)
  std::optional<DensePyramid> dense;           //!< pyramids of the dense refinement
  /** What a registration of another library made of this frame, in its own types (a peer's
   * pyramids or image): made once, the frame being the current one now and the reference next. */
  std::any peer;
  /** The tracker's prediction of the motion to the reference (constant velocity), when it has
   * one: the start of a dense registration when no sparse estimate exists. */
  std::optional<Eigen::Isometry3d> guess;
  /** The camera's velocity at this frame (translation [m/s], rotation vector [rad/s]) in its own
   * frame, when the tracker knows it: a rolling shutter's skew is undone with it. */
  std::optional<Eigen::Matrix<double, 6, 1>> velocity;
};

/** What a registration saw of one frame on its own (the report of a first frame). */
struct FrameFeatures {
  FramePath path;  //!< set by each registration; its refinement part by DenseRefined
  std::size_t orb_features = 0, features = 0;
  StageTimes ms;
};

/** Result of aligning a frame with its reference. */
struct RegistrationResult {
  FrameResult::Status status = FrameResult::Status::TooFewFeatures;
  /** maps points of the current frame into the reference frame (the motion reference -> cur) */
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  std::string detail;  //!< why, when not Ok
  FrameFeatures seen;  //!< path used, feature counts, and the time of every stage
  std::size_t matches = 0, inliers = 0;
  double scale = 0;                            //!< [m] estimator noise scale
  std::vector<Eigen::Vector3f> inlier_points;  //!< current frame's inliers, for display
  /** the sparse fit (photometric or geometric) succeeded; after the dense refinement, whichever
   * start won (false: a result of the refinement from the prediction alone) */
  bool sparse_ok = false;
  bool ok() const { return status == FrameResult::Status::Ok; }
};

/** A way of registering two frames. Implementations may keep state (e.g. a solver made on the
 * first frame) but not the reference: the tracker owns the frames. */
class Registration {
 public:
  virtual ~Registration() = default;
  /** Computes what this registration needs of `frame` (at most once per frame). */
  virtual FrameFeatures prepare(Frame& frame) = 0;
  /** Aligns prepared `cur` with prepared `ref` (which may gain lazily computed features). */
  virtual RegistrationResult align(Frame& cur, Frame& ref) = 0;
};

struct OdometryParams;

/** The product's registrations: hybrid, rgb_only or depth_only from `params.method`, refined
 * (DenseRefined) with [Dense] enabled: with `refine_min_inliers` > 0 only the sparse fits on as
 * many inliers. Throws ConfigError for a baseline or peer method (made by rgbd_baselines). */
std::unique_ptr<Registration> makeRegistration(const OdometryParams& params,
                                               std::size_t refine_min_inliers = 0);

}  // namespace hrgbd
