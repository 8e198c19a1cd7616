#pragma once
/** \file FrameResult.h
 * What the odometry reports for one frame, and the per-stage timing it carries. */
#include <mrpt/poses/CPose3D.h>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "rgbd_core/Timing.h"

namespace hrgbd {

/** [ms] time spent per stage of one frame. */
struct StageTimes {
  double prepare = 0, features = 0, matching = 0, estimation = 0, refine = 0, total = 0;
  StageTimes& operator+=(const StageTimes& o);
};

/** How a frame was registered: the sparse path that ran, and whether the dense refinement ran and
 * which start gave the pose. Printed in frames.csv as two words, `path` and `refined`. */
struct FramePath {
  enum class Sparse {
    None,         //!< no registration ran (bad input)
    Photometric,  //!< ORB features, III-B (also the ransac baselines)
    Geometric,    //!< IS3D + SHOT, III-C to III-F
    Peer,         //!< a peer library's own whole-image registration (OpenCV, Open3D)
  };
  enum class Refined {
    None,        //!< the dense refinement did not run
    Sparse,      //!< it ran, and the pose is its refinement of the sparse fit
    Prediction,  //!< it ran, and the pose is its refinement of the motion prediction
    Refused,     //!< it ran, and its result was not taken (the sparse fit stands, or the frame
                 //!< is flagged)
  };
  Sparse sparse = Sparse::None;
  Refined refined = Refined::None;
  bool operator==(const FramePath& o) const { return sparse == o.sparse && refined == o.refined; }
  bool operator!=(const FramePath& o) const { return !(*this == o); }
};
/** "none", "photometric", "geometric", "peer" (frames.csv's `path`). */
const char* toString(FramePath::Sparse s);
/** "none", "sparse", "prediction", "refused" (frames.csv's `refined`). */
const char* toString(FramePath::Refined r);
/** One label for reports and the viewer: "photometric", "photometric+dense",
 * "photometric+dense(prediction)", "photometric+dense(refused)", ... */
std::string toString(const FramePath& p);

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
    /** the scene does not constrain every direction of the motion (no texture or texture in one
     * direction only, and a plane or a corridor): DenseParams::min_texture_pairs; predicted */
    Degenerate,
  };
  double t = 0;  //!< [s]
  mrpt::poses::CPose3D pose;
  Status status = Status::FirstFrame;
  std::string detail;            //!< human-readable reason when not Ok
  FramePath path;                //!< how it was registered
  std::size_t orb_features = 0;  //!< ORB features with depth (what the hybrid switch counts)
  std::size_t features = 0, matches = 0, inliers = 0;  //!< on the path used
  double scale = 0;                                    //!< [m] estimator noise scale
  /** [m] the current frame's inlier features (optical frame), for display; empty on failure */
  std::vector<Eigen::Vector3f> inlier_points;
  /** became the reference for the next frames: registered, or the last of
   * keyframe_after_failures flagged frames in a row (at its predicted pose) */
  bool keyframe = false;
  /** SLAM mode: the keyframe is a node of the pose graph (set by KeyframeSlam::add(); the
   * tracker's keyframes closer than [Slam] node_spacing to the last node are not) */
  bool node = false;
  StageTimes ms;  //!< [ms] per stage
  bool registered() const { return status == Status::Ok || status == Status::FirstFrame; }
};
const char* toString(FrameResult::Status s);

}  // namespace hrgbd
