#pragma once
/** \file Live.h
 * The live app, in the spirit of MRPT's kinect-3d-slam: a grabber thread feeds the FrameLoop,
 * registered frames grow a coloured map, and an MRPT 3D window shows it all. Any recorded
 * source (rawlog, TUM folder, simulator output) runs as if live. `rgbd-live` is a thin main. */
#include <iosfwd>
#include <string>

namespace hrgbd {

struct LiveOptions {
  std::string config;             //!< INI file ("" = defaults); [Odometry], [Map], [OpenNI2]
  std::string input = "openni2";  //!< "openni2", a rawlog or a TUM folder
  double rate = 1.0;              //!< recorded sources: x recorded speed; 0 = as fast as possible
  /** recorded sources played as a sensor: frames on their time stamps (x `rate`), those that
   * arrive while the tracker is behind dropped, exactly as the sensor's grabber does */
  bool realtime = false;
  std::string save_prefix = "live_";  //!< [s] writes <prefix>map.ply, map.3Dscene, trajectory.txt
  /** < 0: keep the window until closed or [q]; >= 0: close this many seconds after the data ends
   * (scripts and the Xvfb test). */
  double hold_seconds = -1;
  int max_frames = 0;    //!< stop after N frames (0 = all)
  bool slam = false;     //!< SLAM mode on, whatever [Slam] enabled says
  bool no_slam = false;  //!< SLAM mode off, whatever [Slam] enabled says
};

/** Runs until the data ends (and the hold expires) or the window is closed. Throws with a clear
 * message when the input cannot be opened (e.g. no OpenNI2 sensor) or there is no display. */
void runLive(const LiveOptions& options, std::ostream& log);

}  // namespace hrgbd
