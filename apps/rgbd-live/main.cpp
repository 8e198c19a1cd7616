// rgbd-live: the odometry live, with the growing coloured map in an MRPT 3D window.
#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <iostream>

#include "rgbd_live/Live.h"

int main(int argc, char** argv) {
  try {
    TCLAP::CmdLine cmd("rgbd-live: live RGB-D odometry and coloured map (MRPT 3D window)", ' ',
                       "0.1");
    TCLAP::ValueArg<std::string> config("c", "config", "INI file", false, "", "FILE.ini", cmd);
    TCLAP::ValueArg<std::string> input("i", "input", "'openni2' (default), rawlog or TUM folder",
                                       false, "openni2", "INPUT", cmd);
    TCLAP::ValueArg<double> rate("", "rate", "recorded input: x recorded speed (1); 0 = fastest",
                                 false, 1.0, "R", cmd);
    TCLAP::ValueArg<std::string> prefix("", "save-prefix", "[s] saves PREFIXmap.ply etc.", false,
                                        "live_", "PREFIX", cmd);
    TCLAP::ValueArg<double> hold("", "hold", "close S seconds after the data ends and save", false,
                                 -1, "S", cmd);
    TCLAP::ValueArg<int> frames("n", "max-frames", "stop after N frames", false, 0, "N", cmd);
    cmd.parse(argc, argv);
    hrgbd::runLive({config.getValue(), input.getValue(), rate.getValue(), prefix.getValue(),
                    hold.getValue(), frames.getValue()},
                   std::cout);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "rgbd-live: error: " << e.what() << "\n";
    return 1;
  }
}
