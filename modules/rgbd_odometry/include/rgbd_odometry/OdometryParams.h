#pragma once
/** \file OdometryParams.h
 * Parameters of the odometry: INI section [Odometry] and the stage sections it owns. */
#include <string>

#include "rgbd_core/Params.h"
#include "rgbd_odometry/DenseRefinement.h"
#include "rgbd_odometry/GeometricParams.h"
#include "rgbd_odometry/MsseEstimator.h"
#include "rgbd_odometry/OrbFeatures.h"

namespace hrgbd {

/** Registration methods: the paper's, its baselines (Tables I and II) and the dense odometries
 * of OpenCV contrib and Open3D as peers. INI key [Odometry] method, names below
 * (MRPT_FILL_ENUM_CUSTOM_NAME). */
enum class Method {
  Hybrid,     //!< ORB + MSSE; geometric features when too few ORB features (paper), see
              //!< min_photometric_inliers and geometric_fallback for the additions
  RgbOnly,    //!< ORB + MSSE always
  DepthOnly,  //!< geometric (IS3D + SHOT) + MSSE always
  Ransac,     //!< ORB + RANSAC
  RansacIcp,  //!< ORB + RANSAC, refined by ICP on ~15,000 points
  // Peers: dense frame-to-frame odometries of other libraries, fed the same prepared frames
  OpencvRgbd,     //!< cv::rgbd::RgbdOdometry (photometric, dense)
  OpencvIcp,      //!< cv::rgbd::ICPOdometry (point-to-plane on the depth)
  OpencvRgbdIcp,  //!< cv::rgbd::RgbdICPOdometry (both)
  Open3dColor,    //!< Open3D's ComputeRGBDOdometry, photometric term
  Open3dHybrid,   //!< Open3D's ComputeRGBDOdometry, photometric + depth term
};
/** The method named `name` (INI and command-line spelling, e.g. "rgb_only"); throws ConfigError
 * listing the names otherwise. */
Method parseMethod(const std::string& name);
std::string toString(Method m);
/** hybrid, rgb_only, depth_only: the paths of the paper, which the dense refinement and
 * keyframe tracking extend; the others are baselines and peers. */
inline bool isProductMethod(Method m) {
  return m == Method::Hybrid || m == Method::RgbOnly || m == Method::DepthOnly;
}

/** What to do with the pose of a frame that cannot be registered. */
enum class FailurePolicy {
  ConstantVelocity,  //!< the last registered motion is repeated
  Hold,              //!< the pose stays where it was
};

}  // namespace hrgbd

// The INI and command-line names of the enums (MRPT's TEnumType, as read_enum uses).
MRPT_ENUM_TYPE_BEGIN(hrgbd::Method)
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::Method::Hybrid, "hybrid");
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::Method::RgbOnly, "rgb_only");
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::Method::DepthOnly, "depth_only");
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::Method::Ransac, "ransac");
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::Method::RansacIcp, "ransac_icp");
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::Method::OpencvRgbd, "opencv_rgbd");
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::Method::OpencvIcp, "opencv_icp");
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::Method::OpencvRgbdIcp, "opencv_rgbd_icp");
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::Method::Open3dColor, "open3d_color");
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::Method::Open3dHybrid, "open3d_hybrid");
MRPT_ENUM_TYPE_END()

MRPT_ENUM_TYPE_BEGIN(hrgbd::FailurePolicy)
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::FailurePolicy::ConstantVelocity, "constant_velocity");
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::FailurePolicy::Hold, "hold");
MRPT_ENUM_TYPE_END()

namespace hrgbd {

/** Parameters of RgbdOdometry. INI section [Odometry]; the stages read [ORB], [Geometric],
 * [MSSE] and [Dense]. The baselines' [RANSAC] and [ICP] are BaselineParams (rgbd_baselines). */
struct OdometryParams : public Params<OdometryParams> {
  Method method = Method::Hybrid;  //!< registration method (all listed in Method)
  int min_orb_features = 50;       //!< [count] fewer ORB features with depth -> geometric path
  /** [count] hybrid only: a photometric registration with fewer inliers is replaced by the
   * geometric path's when that registers (not in the paper; 0 = off). Measured: every good
   * photometric frame had >= 143 inliers, the far plain zig-zag's 9-26. */
  int min_photometric_inliers = 30;
  /** hybrid only: when the photometric path cannot register a frame (too few matches or
   * inliers, ...), try the geometric path before giving up. The paper switches on the feature
   * count alone (false reproduces it). */
  bool geometric_fallback = true;
  /** k' of MSSE on geometric (SHOT) matches, which are mostly outliers (50-80 % measured on the
   * simulated zig-zag and fr3/cabinet), beyond what k_fraction = 0.5 survives. */
  double geometric_k_fraction = 0.2;
  int max_hamming_distance = 64;  //!< [bits] ORB pairs farther apart are never matched
  FailurePolicy on_failure = FailurePolicy::ConstantVelocity;  //!< pose of unregistered frames
  double max_step_translation = 0.5;  //!< [m] larger frame-to-frame motion is flagged as failure
  double max_step_rotation_deg = 30;  //!< [deg] larger frame-to-frame rotation is flagged too
  /** [m] Frame-to-keyframe tracking: frames are registered against the keyframe, which the
   * current frame replaces once it is this far from it. 0 = every registered frame becomes the
   * reference (and a flagged one after keyframe_after_failures): the paper's frame-to-frame
   * chaining (Algorithm 2). The baselines and peers always track frame to frame, as published. */
  double keyframe_max_translation = 0.05;
  double keyframe_max_rotation_deg = 3;  //!< [deg] ... or once it has turned this much
  int keyframe_min_inliers = 0;          //!< [count] ... or was registered on fewer inliers
  /** [count] after this many flagged frames in a row, the last of them becomes the keyframe at
   * its predicted pose (frames that could not be prepared count, and the first flagged frame
   * after them that could is taken); 0 = never: the keyframe stays until a frame registers against
   * it. The baselines and peers never do this, as published. */
  int keyframe_after_failures = 5;
  /** [count] on_failure = constant_velocity extrapolates the last motion over at most this many
   * flagged frames in a row; from the next one on the pose is held (and so is the prediction
   * that starts the refinement), so that a pause in a long flagged run does not turn into metres.
   * 0 = extrapolated over any run. */
  int max_predicted_frames = 5;
  /** [intervals] after a frame that comes more than this many times the mean interval (a running
   * mean) after the previous frame (dropped frames, a sensor that stalled), the frames get no
   * motion prediction as a start of the dense refinement until one registers: across a gap the
   * prediction is a guess that the refinement could settle from into a wrong pose. 0 = always a
   * prediction. */
  double prediction_max_gap = 3;
  OrbParams orb;              //!< section [ORB]
  GeometricParams geometric;  //!< section [Geometric]
  MsseParams msse;            //!< section [MSSE]
  DenseParams dense;          //!< section [Dense]

  template <class P, class V>
  static void declare(P& p, V& v) {
    HRGBD_PARAM(method, "registration method");
    HRGBD_PARAM(min_orb_features, "[count] fewer ORB features: geometric path", Range::atLeast(0));
    HRGBD_PARAM(min_photometric_inliers,
                "[count] hybrid: fewer photometric inliers: geometric if it works (0 = off)",
                Range::atLeast(0));
    HRGBD_PARAM(geometric_fallback, "hybrid: photometric failure -> geometric");
    HRGBD_PARAM(geometric_k_fraction, "k' of MSSE on SHOT matches", Range::openClosed(0, 1));
    HRGBD_PARAM(max_hamming_distance, "[bits] ORB match limit", Range::openClosed(0, 256));
    HRGBD_PARAM(on_failure, "pose of unregistered frames");
    HRGBD_PARAM(max_step_translation, "[m] larger motion per frame: failure", Range::above(0));
    HRGBD_PARAM(max_step_rotation_deg, "[deg] larger rotation per frame: failure",
                Range::openClosed(0, 180));
    HRGBD_PARAM(keyframe_max_translation,
                "[m] new keyframe beyond this distance from it (0 = frame to frame)",
                Range::atLeast(0));
    HRGBD_PARAM(keyframe_max_rotation_deg, "[deg] new keyframe beyond this rotation from it",
                Range::openClosed(0, 180));
    HRGBD_PARAM(keyframe_min_inliers, "[count] new keyframe below this many inliers",
                Range::atLeast(0));
    HRGBD_PARAM(keyframe_after_failures,
                "[count] flagged frames in a row: the last becomes the keyframe (0 = never)",
                Range::atLeast(0));
    HRGBD_PARAM(max_predicted_frames,
                "[count] flagged frames in a row over which the motion is extrapolated (0 = any)",
                Range::atLeast(0));
    HRGBD_PARAM(prediction_max_gap,
                "[intervals] no motion prediction after a longer time gap (0 = always, else > 1)",
                Range::atLeast(0));
    v.section(p.orb, "ORB");
    v.section(p.geometric, "Geometric");
    v.section(p.msse, "MSSE");
    v.section(p.dense, "Dense");
  }
  /** prediction_max_gap is 0 or above 1: a gap of at most one mean interval would take the
   * prediction from every other frame. */
  void checkTogether(const std::string& section) const;
};

}  // namespace hrgbd
