// rgbd-benchmark: sequences x methods from the INI's [Benchmark] section, as markdown tables.
#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <iostream>

#include "rgbd_bench/Benchmark.h"

int main(int argc, char** argv) {
  try {
    TCLAP::CmdLine cmd("rgbd-benchmark: the paper's Tables I-III for our methods and OpenCV peers",
                       ' ', "0.1");
    TCLAP::ValueArg<std::string> config("c", "config", "INI file with a [Benchmark] section", false,
                                        "config.ini", "FILE.ini", cmd);
    TCLAP::UnlabeledMultiArg<std::string> extra(
        "sequences", "further TUM folders or rawlogs (with ground truth) to add", false, "PATH",
        cmd);
    cmd.parse(argc, argv);
    const auto report = hrgbd::runBenchmark(config.getValue(), extra.getValue(), std::cout);
    std::cout << "finished in " << report.seconds << " s\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "rgbd-benchmark: error: " << e.what() << "\n";
    return 1;
  }
}
