// tum2rawlog TUM_FOLDER OUT.rawlog: converts a TUM RGB-D folder into an MRPT rawlog, with the
// ground truth written beside it as OUT_groundtruth.txt.
#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <iostream>

#include "rgbd_core/Config.h"
#include "rgbd_io/RawlogSource.h"
#include "rgbd_io/RawlogWriter.h"
#include "rgbd_io/TumSource.h"

int main(int argc, char** argv) {
  try {
    TCLAP::CmdLine cmd("tum2rawlog: TUM RGB-D folder -> MRPT rawlog (+ ground truth)", ' ', "0.1");
    TCLAP::UnlabeledValueArg<std::string> in("folder", "TUM dataset folder", true, "", "FOLDER",
                                             cmd);
    TCLAP::UnlabeledValueArg<std::string> out("rawlog", "output rawlog", true, "", "OUT.rawlog",
                                              cmd);
    TCLAP::ValueArg<std::string> cfg("c", "config", "INI file with a [TumSource] section", false,
                                     "", "FILE.ini", cmd);
    TCLAP::ValueArg<std::string> images("", "images", "inline|png|jpg (default inline)", false,
                                        "inline", "MODE", cmd);
    cmd.parse(argc, argv);

    hrgbd::TumSourceParams params;
    if (!cfg.getValue().empty())
      hrgbd::loadStrict(params, *hrgbd::loadIniFile(cfg.getValue()), "TumSource");
    const auto mode = images.getValue();
    if (mode != "inline" && mode != "png" && mode != "jpg")
      throw std::runtime_error("--images must be inline, png or jpg");
    hrgbd::TumSource src(in.getValue(), params);
    std::cout << src.describe() << "\n";
    hrgbd::RawlogWriter writer(out.getValue(), mode == "inline" ? hrgbd::ImageStorage::Inline
                                               : mode == "png"  ? hrgbd::ImageStorage::ExternalPng
                                                               : hrgbd::ImageStorage::ExternalJpeg);
    while (auto obs = src.next()) writer.write(*obs);
    std::cout << "wrote " << writer.written() << " frames to " << out.getValue() << "\n";
    if (!src.groundTruth().empty()) {
      const auto gt = hrgbd::groundTruthPathFor(out.getValue());
      hrgbd::saveTumTrajectory(gt, src.groundTruth());
      std::cout << "wrote " << src.groundTruth().size() << " ground-truth poses to " << gt << "\n";
    }
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "tum2rawlog: error: " << e.what() << "\n";
    return 1;
  }
}
