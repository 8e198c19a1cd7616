#pragma once
/** \file Playback.h
 * The playback application: any FrameSource through the FrameLoop into the sinks the options ask
 * for (TUM trajectory, per-frame CSV, coloured map, rawlog and simplemap with poses, progress
 * bar), then evaluation against ground truth. `hybrid-rgbd-odometry` is a thin main over
 * runPlayback(). */
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "rgbd_app/AppConfig.h"
#include "rgbd_eval/Evaluate.h"
#include "rgbd_odometry/RgbdOdometry.h"
#include "rgbd_slam/KeyframeSlam.h"

namespace hrgbd {

/** Command-line options; empty strings mean "from the INI [Playback] section". */
struct PlaybackOptions {
  std::string config;      //!< INI file ("" = built-in defaults)
  std::string input;       //!< rawlog, TUM folder or "openni2"
  std::string trajectory;  //!< output TUM trajectory
  std::string csv;         //!< output per-frame CSV ("" = none)
  std::string method;      //!< overrides [Odometry] method
  std::string plot;        //!< evaluation figure, .png/.svg/.pdf ("" = none)
  int max_frames = 0;      //!< stop after this many frames (0 = all)
  bool progress = true;    //!< progress line on stderr (rgbd_core/Progress.h)
  /** a recording played as a sensor (rgbd_io/Grabber.h): frames on their time stamps, those
   * arriving while the tracker is behind dropped and counted; always so for "openni2" */
  bool realtime = false;
  // Map and MRPT outputs ("" = from [Playback], where "" = none)
  std::string output_rawlog;  //!< the frames with their estimated pose as sensorPose
  std::string simplemap;      //!< CSimpleMap of (pose, frame) for observations2map
  std::string map_ply;        //!< coloured map, PLY
  std::string map_scene;      //!< coloured map + camera path, .3Dscene
  bool slam = false;          //!< SLAM mode on, whatever [Slam] enabled says
  bool no_slam = false;       //!< SLAM mode off, whatever [Slam] enabled says
  std::string graph;          //!< SLAM mode: the pose graph, MRPT text format ("" = [Playback])
  bool ini_outputs = true;    //!< false: only the outputs set here (CSV, map, rawlog) are written

  std::string progress_label;  //!< leads the progress line ("" = none)
};

/** Summary of a run. */
struct PlaybackSummary {
  std::size_t frames = 0, registered = 0;
  std::size_t dropped = 0;  //!< frames the grabber dropped, the tracker being behind (realtime)
  std::vector<FrameResult> results;
  bool evaluated = false;
  EvalResult eval;  //!< valid when evaluated (toText() / toJson() format it)
  double median_ms = 0, p95_ms = 0;
  std::size_t map_points = 0;  //!< points in the coloured map (when a map output was asked)
  bool slam = false;           //!< ran in SLAM mode: poses are the optimised ones
  SlamStats slam_stats;        //!< valid in SLAM mode
  std::vector<RelativeMeasurement> loops;  //!< SLAM mode: the loop edges that hold
  RelativeCheck loop_check;                //!< the loops against the ground truth (when evaluated)
};

/** Runs the whole job; progress and results are written to `log`. Throws on bad configuration,
 * unreadable input or an output that cannot be written; frames that cannot be registered are
 * flagged in the results. Before anything is written, an output that would overwrite an input
 * (the input's files, the configuration file) or another output is refused (checkJobPaths():
 * UsageError when the command-line option named it, ConfigError for a [Playback] key). Every
 * output is written in full or not at all (OutputFile.h): a run that fails leaves no partial
 * trajectory or CSV under the output's name. */
PlaybackSummary runPlayback(const PlaybackOptions& options, std::ostream& log);

}  // namespace hrgbd
