// hybrid-rgbd-odometry: runs the odometry over a rawlog, TUM folder or live sensor.
#include <iostream>

#include "rgbd_app/Playback.h"
#include "rgbd_cli/CommandLine.h"
#include "rgbd_core/JobPaths.h"

int main(int argc, char** argv) {
  using TCLAP::ValueArg;
  using Text = ValueArg<std::string>;
  hrgbd::CommandLine cmd("hybrid-rgbd-odometry",
                         "RGB-D odometry (ORB / geometric features + MSSE)");
  Text config("c", "config", "INI file", false, "", "FILE.ini", cmd);
  Text input("i", "input", "rawlog, TUM folder, OpenNI recording (.oni) or 'openni2'", false, "",
             "INPUT", cmd);
  Text traj("t", "trajectory", "output trajectory (TUM format)", false, "", "OUT.txt", cmd);
  Text method("m", "method", "odometry method (default: the INI's [Odometry] method)", false, "",
              cmd.oneOf<hrgbd::Method>(), cmd);
  Text csv("", "csv", "per-frame CSV", false, "", "OUT.csv", cmd);
  Text plot("", "plot", "evaluation figure (with ground truth): .png, .svg or .pdf", false, "",
            "OUT.png", cmd);
  ValueArg<int> max_frames("n", "max-frames", "stop after N frames (0 = all)", false, 0,
                           cmd.atLeast(0, "N"), cmd);
  Text out_rawlog("", "output-rawlog", "the frames with their estimated poses (RawLogViewer)",
                  false, "", "OUT.rawlog", cmd);
  Text simplemap("", "simplemap", "(pose, frame) pairs for observations2map", false, "",
                 "OUT.simplemap", cmd);
  Text ply("", "map-ply", "coloured map as PLY", false, "", "OUT.ply", cmd);
  Text scene("", "map-scene", "coloured map and path as .3Dscene", false, "", "OUT.3Dscene", cmd);
  TCLAP::SwitchArg slam("", "slam", "SLAM mode on: loop closures and pose-graph optimisation", cmd);
  TCLAP::SwitchArg no_slam("", "no-slam", "SLAM mode off: the odometry alone", cmd);
  Text graph("", "graph", "SLAM mode: the pose graph, MRPT text format", false, "", "OUT.graph",
             cmd);
  TCLAP::SwitchArg realtime("", "realtime",
                            "play the recording as a sensor: frames on their time stamps, those "
                            "arriving while the tracker is behind dropped (and counted)",
                            cmd);
  TCLAP::SwitchArg quiet("q", "quiet", "no progress bar", cmd);
  TCLAP::SwitchArg print("", "print-config", "print the effective configuration and exit", cmd);
  return cmd.run(argc, argv, [&] {
    if (print.getValue()) {
      std::cout << hrgbd::effectiveConfig(config.getValue());
      return;
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
    o.realtime = realtime.getValue();
    o.output_rawlog = out_rawlog.getValue();
    o.simplemap = simplemap.getValue();
    o.map_ply = ply.getValue();
    o.map_scene = scene.getValue();
    o.slam = slam.getValue();
    o.no_slam = no_slam.getValue();
    o.graph = graph.getValue();
    // an output on stdout (-t /dev/stdout): the messages go to stderr, not into it
    const bool on_stdout =
        hrgbd::writesStandardOutput({o.trajectory, o.csv, o.graph, o.output_rawlog, o.simplemap,
                                     o.map_ply, o.map_scene, o.plot});
    hrgbd::runPlayback(o, on_stdout ? std::cerr : std::cout);
  });
}
