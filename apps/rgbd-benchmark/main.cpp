// rgbd-benchmark: sequences x methods from the INI's [Benchmark] section, as markdown tables.
#include <iostream>
#include <map>

#include "rgbd_bench/Benchmark.h"
#include "rgbd_cli/CommandLine.h"
#include "rgbd_core/Progress.h"

int main(int argc, char** argv) {
  hrgbd::CommandLine cmd("rgbd-benchmark",
                         "the paper's Tables I-III for our methods and OpenCV peers");
  TCLAP::ValueArg<std::string> config("c", "config", "INI file with a [Benchmark] section", false,
                                      "config.ini", "FILE.ini", cmd);
  TCLAP::UnlabeledMultiArg<std::string> extra(
      "sequences", "further TUM folders or rawlogs (with ground truth) to add", false, "PATH", cmd);
  TCLAP::SwitchArg quiet("q", "quiet", "no progress lines", cmd);
  TCLAP::SwitchArg quick("", "quick",
                         "the quick preset: hybrid and opencv_rgbd, near sweeps and the real "
                         "sequences, at most 60 frames a run, into benchmark_quick/ (the options "
                         "below still override)",
                         cmd);
  // each overrides the [Benchmark] key of the same name
  TCLAP::ValueArg<std::string> methods("", "methods", "[Benchmark] methods, separated by spaces",
                                       false, "", "LIST", cmd);
  TCLAP::ValueArg<std::string> sim_scenes(
      "", "sim-scenes", "[Benchmark] sim_scenes, separated by spaces (\"\" = none)", false, "",
      "LIST", cmd);
  TCLAP::ValueArg<std::string> real("", "real-sequences",
                                    "[Benchmark] real_sequences, separated by spaces (\"\" = none)",
                                    false, "", "LIST", cmd);
  return cmd.run(argc, argv, [&] {
    auto overrides =
        quick.getValue() ? hrgbd::quickBenchmark() : std::map<std::string, std::string>{};
    if (methods.isSet()) overrides["methods"] = methods.getValue();
    if (sim_scenes.isSet()) overrides["sim_scenes"] = sim_scenes.getValue();
    if (real.isSet()) overrides["real_sequences"] = real.getValue();
    const auto report = hrgbd::runBenchmark(config.getValue(), extra.getValue(), std::cout,
                                            !quiet.getValue(), overrides);
    std::cout << "finished in " << hrgbd::formatDuration(report.seconds) << "\n";
  });
}
