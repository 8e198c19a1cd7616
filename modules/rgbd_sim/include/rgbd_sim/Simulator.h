#pragma once
/** \file Simulator.h
 * RGB-D sequences with exact ground truth: a Scene, a camera path (procedural sweep or replayed
 * real hand-held motion) and the Kinect model, written as a rawlog, a TUM folder and/or an OpenNI
 * recording. */
#include <string>
#include <vector>

#include "rgbd_core/JobPaths.h"
#include "rgbd_core/Params.h"
#include "rgbd_core/Progress.h"
#include "rgbd_core/Trajectory.h"
#include "rgbd_io/RawlogWriter.h"
#include "rgbd_sim/Render.h"

namespace hrgbd::sim {

/** Parameters of simulate(). INI section [Simulator]. */
struct SimParams : public Params<SimParams> {
  std::string scene =
      "desk";        //!< texture|structure|structure_texture|desk|wall|object|stripes|corridor
  bool far = false;  //!< camera at ~2 m instead of ~1 m
  int frames = 30;   //!< [count]
  double fps = 30;   //!< [Hz]
  int seed = 1;      //!< noise and jitter seed (same seed, same sequence)
  /** "sweep" (procedural sweep along the structure with hand-held jitter), "loop" (an orbit of
   * +-35 deg about the scene that returns to its start after the last frame: a loop to close; it
   * lasts frames / fps, so 960 frames at 30 Hz orbit in 32 s, and under ~300 frames it is
   * faster than hand-held motion) or
   * a TUM trajectory file whose motion is replayed, moved so that the point it looked at is the
   * scene's look_at. */
  std::string motion = "sweep";
  /** [m/s] a person-sized textured box walks back and forth across the scene (withWalker();
   * a moving object); 0 = none, at most 10 */
  double walker_speed = 0;
  KinectModel sensor;  //!< its keys are in this section too

  template <class P, class V>
  static void declare(P& p, V& v) {
    HRGBD_PARAM(scene, "scene type", OneOf{sceneTypes()});
    HRGBD_PARAM(far, "camera at ~2 m (true) or ~1 m (false)");
    HRGBD_PARAM(frames, "[count] frames to render", Range::atLeast(1));
    HRGBD_PARAM(fps, "[Hz] frame rate", Range::openClosed(0, 1000));
    HRGBD_PARAM(seed, "noise and jitter seed");
    HRGBD_PARAM(motion, "sweep, loop, or a TUM trajectory file to replay");
    HRGBD_PARAM(walker_speed, "[m/s] a moving person-sized box (0 = none)", Range::closed(0, 10));
    v.merge(p.sensor);  // the sensor model's keys are in the same section
  }
};

/** True for the motions the simulator makes itself ("sweep", "loop"); others are files. */
inline bool isProceduralMotion(const std::string& motion) {
  return motion == "sweep" || motion == "loop";
}

/** Camera trajectory (optical frame in the world) sampled at `times`. */
Trajectory cameraPath(const Scene& scene, const SimParams& params,
                      const std::vector<double>& times);

/** The point a hand-held camera path looked at: nearest to all its optical axes (least squares),
 * or about `distance` [m] ahead of the first camera when the axes are near-parallel. When the
 * cameras do not see that point (median depth) at 0.5-3 x `distance` within the sensor's range,
 * the mean of the points `distance` ahead of each camera; when they do not see that either (a
 * camera turning all round), the point `distance` ahead of the first camera. */
Eigen::Vector3d lookedAtPoint(const Trajectory& path, double distance,
                              const KinectModel& sensor = {});

/** The first pose of a sweep: at `distance` from look_at along view_dir, looking at look_at. */
mrpt::poses::CPose3D lookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target);

struct SimOutputs {
  std::string rawlog;  //!< "" = none; ground truth goes to <stem>_groundtruth.txt
  /** "" = none; rgb/, depth/, rgb.txt, depth.txt, groundtruth.txt and calibration.txt (the
   * camera, "fx fy cx cy", read by TumSource) */
  std::string tum_folder;
  ImageStorage images = ImageStorage::Inline;  //!< colour storage in the rawlog
  /** "" = none; an OpenNI recording (.oni, OniWriter.h: depth in mm, colour RGB888, uncompressed)
   * whose clock starts at 0 with the first frame; ground truth in that clock goes to
   * <stem>_groundtruth.txt. */
  std::string oni;
};

/** Share of the image below which a frame's depth counts as sparse (SimResult). */
constexpr double kSparseDepthShare = 0.25;

struct SimResult {
  int frames = 0;
  double ms_per_frame = 0;  //!< [ms] median render + sensor model time
  /** frames with depth on under kSparseDepthShare of the image: the camera looks past the
   * scene (a replayed motion that leaves it) */
  int sparse_depth_frames = 0;
  Trajectory ground_truth;
};

/** The files and folders simulate() writes for `outputs`, named after rgbd-simulate's options,
 * for checkJobPaths() against the inputs (motion file, configuration). */
std::vector<JobPath> writtenFiles(const SimOutputs& outputs);

/** Throws UsageError when `folder` (rgbd-simulate --tum) holds a TUM dataset rgbd-simulate did not
 * write: an rgb.txt or depth.txt without the simulator's "# file: rgbd-simulate" line, or a
 * groundtruth.txt or calibration.txt beside no such list. Its lists, ground truth and camera would
 * be replaced (a real dataset's, for one). A folder the simulator wrote may be written again. */
void checkTumOutputFolder(const std::string& folder);

/** Renders and writes the sequence. Throws for bad parameters or unwritable outputs. Every file
 * is written in full or not at all (OutputFile.h); the rawlog's, the lists' and the ground
 * truth's names appear only once the whole sequence is written. `progress` (optional) is updated
 * after each frame; the caller finishes it. */
SimResult simulate(const SimParams& params, const SimOutputs& outputs,
                   Progress* progress = nullptr);

}  // namespace hrgbd::sim
