// hybrid-rgbd-odometry: runs the odometry over a rawlog, TUM folder or live sensor.
#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <iostream>

#include "rgbd_app/Playback.h"

int main(int argc, char** argv) {
  try {
    TCLAP::CmdLine cmd("hybrid-rgbd-odometry: RGB-D odometry (ORB / geometric features + MSSE)",
                       ' ', "0.1");
    TCLAP::ValueArg<std::string> config("c", "config", "INI file", false, "", "FILE.ini", cmd);
    TCLAP::ValueArg<std::string> input("i", "input", "rawlog, TUM folder or 'openni2'", false, "",
                                       "INPUT", cmd);
    TCLAP::ValueArg<std::string> traj("t", "trajectory", "output trajectory (TUM format)", false,
                                      "", "OUT.txt", cmd);
    TCLAP::ValueArg<std::string> method(
        "m", "method", "hybrid|rgb_only|depth_only|ransac|ransac_icp", false, "", "METHOD", cmd);
    TCLAP::ValueArg<std::string> csv("", "csv", "per-frame CSV", false, "", "OUT.csv", cmd);
    TCLAP::ValueArg<std::string> plot("", "plot", "evaluation PNG (with ground truth)", false, "",
                                      "OUT.png", cmd);
    TCLAP::ValueArg<int> max_frames("n", "max-frames", "stop after N frames", false, 0, "N", cmd);
    TCLAP::SwitchArg quiet("q", "quiet", "no progress bar", cmd);
    TCLAP::SwitchArg print("", "print-config", "print the effective configuration and exit", cmd);
    cmd.parse(argc, argv);
    if (print.getValue()) {
      std::cout << hrgbd::effectiveConfig(config.getValue());
      return 0;
    }
    hrgbd::PlaybackOptions o{config.getValue(),     input.getValue(),  traj.getValue(),
                             csv.getValue(),        method.getValue(), plot.getValue(),
                             max_frames.getValue(), !quiet.getValue()};
    hrgbd::runPlayback(o, std::cout);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "hybrid-rgbd-odometry: error: " << e.what() << "\n";
    return 1;
  }
}
