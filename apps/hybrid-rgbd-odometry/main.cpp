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
        "m", "method",
        "hybrid|rgb_only|depth_only|ransac|ransac_icp|opencv_rgbd|opencv_icp|opencv_rgbd_icp",
        false, "", "METHOD", cmd);
    TCLAP::ValueArg<std::string> csv("", "csv", "per-frame CSV", false, "", "OUT.csv", cmd);
    TCLAP::ValueArg<std::string> plot("", "plot", "evaluation PNG (with ground truth)", false, "",
                                      "OUT.png", cmd);
    TCLAP::ValueArg<int> max_frames("n", "max-frames", "stop after N frames", false, 0, "N", cmd);
    TCLAP::ValueArg<std::string> out_rawlog("", "output-rawlog",
                                            "the frames with their estimated poses (RawLogViewer)",
                                            false, "", "OUT.rawlog", cmd);
    TCLAP::ValueArg<std::string> simplemap("", "simplemap",
                                           "(pose, frame) pairs for observations2map", false, "",
                                           "OUT.simplemap", cmd);
    TCLAP::ValueArg<std::string> ply("", "map-ply", "coloured map as PLY", false, "", "OUT.ply",
                                     cmd);
    TCLAP::ValueArg<std::string> scene("", "map-scene", "coloured map and path as .3Dscene", false,
                                       "", "OUT.3Dscene", cmd);
    TCLAP::SwitchArg quiet("q", "quiet", "no progress bar", cmd);
    TCLAP::SwitchArg print("", "print-config", "print the effective configuration and exit", cmd);
    cmd.parse(argc, argv);
    if (print.getValue()) {
      std::cout << hrgbd::effectiveConfig(config.getValue());
      return 0;
    }
    hrgbd::PlaybackOptions o;
    o.config = config.getValue();
    o.input = input.getValue();
    o.trajectory = traj.getValue();
    o.csv = csv.getValue();
    o.method = method.getValue();
    o.plot = plot.getValue();
    o.max_frames = max_frames.getValue();
    o.progress = !quiet.getValue();
    o.output_rawlog = out_rawlog.getValue();
    o.simplemap = simplemap.getValue();
    o.map_ply = ply.getValue();
    o.map_scene = scene.getValue();
    hrgbd::runPlayback(o, std::cout);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "hybrid-rgbd-odometry: error: " << e.what() << "\n";
    return 1;
  }
}
