// tum2rawlog TUM_FOLDER OUT.rawlog: converts a TUM RGB-D folder into an MRPT rawlog, with the
// ground truth written beside it as OUT_groundtruth.txt.
#include <unistd.h>

#include <iostream>
#include <vector>

#include "rgbd_cli/CommandLine.h"
#include "rgbd_core/Config.h"
#include "rgbd_core/Interrupt.h"
#include "rgbd_core/JobPaths.h"
#include "rgbd_core/Progress.h"
#include "rgbd_io/RawlogSource.h"
#include "rgbd_io/RawlogWriter.h"
#include "rgbd_io/TumSource.h"

int main(int argc, char** argv) {
  hrgbd::CommandLine cmd("tum2rawlog", "TUM RGB-D folder -> MRPT rawlog (+ ground truth)");
  TCLAP::UnlabeledValueArg<std::string> in("folder", "TUM dataset folder", true, "", "FOLDER", cmd);
  TCLAP::UnlabeledValueArg<std::string> out("rawlog", "output rawlog", true, "", "OUT.rawlog", cmd);
  TCLAP::ValueArg<std::string> cfg("c", "config", "INI file with a [TumSource] section", false, "",
                                   "FILE.ini", cmd);
  TCLAP::ValueArg<std::string> images("", "images", "colour storage (default inline)", false,
                                      "inline", cmd.oneOf<hrgbd::ImageStorage>(), cmd);
  TCLAP::SwitchArg quiet("q", "quiet", "no progress line", cmd);
  return cmd.run(argc, argv, [&] {
    hrgbd::TumSourceParams params;
    if (!cfg.getValue().empty())
      params.loadFromConfigFile(*hrgbd::loadIniFile(cfg.getValue()), "TumSource");
    hrgbd::TumSource src(in.getValue(), params);
    const auto storage =
        hrgbd::parseEnum<hrgbd::ImageStorage>(images.getValue(), "command line", "images");
    // A device or FIFO (/dev/stdout) has no folder to put the ground truth in.
    const auto gt = hrgbd::groundTruthOutputFor(out.getValue());
    // the rawlog on stdout: the messages go to stderr, not into it
    std::ostream& log = hrgbd::writesStandardOutput({out.getValue()}) ? std::cerr : std::cout;
    // Nothing is written over the folder's lists, images or ground truth, or the INI file.
    auto inputs = src.inputs();
    inputs.push_back({cfg.getValue(), "the configuration file (--config)"});
    std::vector<hrgbd::JobPath> outputs{{out.getValue(), "the output rawlog", false, true},
                                        {gt, "the output rawlog's ground truth", false, true}};
    if (storage != hrgbd::ImageStorage::Inline)
      outputs.push_back(
          {hrgbd::imagesFolderFor(out.getValue()), "the output rawlog's image folder", true, true});
    hrgbd::checkJobPaths(inputs, outputs);
    log << src.describe() << "\n";
    hrgbd::RawlogWriter writer(out.getValue(), storage);
    hrgbd::ProgressParams pp;
    pp.total = src.size();
    pp.terminal = isatty(STDERR_FILENO);
    hrgbd::Progress progress(std::cerr, pp);
    std::size_t done = 0;
    while (auto obs = src.next()) {
      hrgbd::checkInterrupt();
      writer.write(*obs);
      if (!quiet.getValue()) progress.update(++done);
    }
    writer.close();
    if (!quiet.getValue()) progress.finish();
    log << "wrote " << writer.written() << " frames to " << out.getValue() << "\n";
    if (!src.groundTruth().empty() && gt.empty())
      std::cerr << "tum2rawlog: note: the " << src.groundTruth().size()
                << " ground-truth poses are not written: '" << out.getValue()
                << "' is not a regular file, so no <name>_groundtruth.txt goes beside it\n";
    if (!src.groundTruth().empty() && !gt.empty()) {
      hrgbd::saveTumTrajectory(gt, src.groundTruth());
      log << "wrote " << src.groundTruth().size() << " ground-truth poses to " << gt << "\n";
    }
  });
}
