// rgbd-benchmark: sequences x methods from the INI's [Benchmark] section, as markdown tables.
#include <iostream>

#include "rgbd_bench/Benchmark.h"
#include "rgbd_cli/CommandLine.h"

int main(int argc, char** argv) {
  hrgbd::CommandLine cmd("rgbd-benchmark",
                         "the paper's Tables I-III for our methods and OpenCV peers");
  TCLAP::ValueArg<std::string> config("c", "config", "INI file with a [Benchmark] section", false,
                                      "config.ini", "FILE.ini", cmd);
  TCLAP::UnlabeledMultiArg<std::string> extra(
      "sequences", "further TUM folders or rawlogs (with ground truth) to add", false, "PATH", cmd);
  TCLAP::SwitchArg quiet("q", "quiet", "no progress lines", cmd);
  return cmd.run(argc, argv, [&] {
    const auto report =
        hrgbd::runBenchmark(config.getValue(), extra.getValue(), std::cout, !quiet.getValue());
    std::cout << "finished in " << report.seconds << " s\n";
  });
}
