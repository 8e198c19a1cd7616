// rgbd-live: the odometry live, with the growing coloured map in an MRPT 3D window.
#include <iostream>

#include "rgbd_cli/CommandLine.h"
#include "rgbd_live/Live.h"

int main(int argc, char** argv) {
  hrgbd::CommandLine cmd("rgbd-live", "live RGB-D odometry and coloured map (MRPT 3D window)");
  TCLAP::ValueArg<std::string> config("c", "config", "INI file", false, "", "FILE.ini", cmd);
  TCLAP::ValueArg<std::string> input("i", "input",
                                     "'openni2' (default), rawlog, TUM folder or .oni recording",
                                     false, "openni2", "INPUT", cmd);
  TCLAP::ValueArg<double> rate("", "rate", "recorded input: x recorded speed (1); 0 = fastest",
                               false, 1.0, cmd.atLeast(0.0, "R"), cmd);
  TCLAP::SwitchArg realtime("", "realtime",
                            "recorded input played as a sensor: frames on their time stamps (x "
                            "--rate), those arriving while the tracker is behind dropped",
                            cmd);
  TCLAP::ValueArg<std::string> prefix("", "save-prefix", "[s] saves PREFIXmap.ply etc.", false,
                                      "live_", "PREFIX", cmd);
  // Without --hold the window stays until it is closed or [q] (hold_seconds < 0 inside).
  TCLAP::ValueArg<double> hold("", "hold",
                               "close S (>= 0) seconds after the data ends and save; without it "
                               "the window stays until it is closed or [q]",
                               false, -1, cmd.atLeast(0.0, "S"), cmd);
  TCLAP::SwitchArg slam("", "slam", "SLAM mode on: loops shown, the map snaps to optimised poses",
                        cmd);
  TCLAP::SwitchArg no_slam("", "no-slam", "SLAM mode off: the odometry alone", cmd);
  TCLAP::ValueArg<int> frames("n", "max-frames", "stop after N frames (0 = all)", false, 0,
                              cmd.atLeast(0, "N"), cmd);
  return cmd.run(argc, argv, [&] {
    hrgbd::LiveOptions o;
    o.config = config.getValue();
    o.input = input.getValue();
    o.rate = rate.getValue();
    o.realtime = realtime.getValue();
    o.save_prefix = prefix.getValue();
    o.hold_seconds = hold.getValue();
    o.slam = slam.getValue();
    o.no_slam = no_slam.getValue();
    o.max_frames = frames.getValue();
    hrgbd::runLive(o, std::cout);
  });
}
