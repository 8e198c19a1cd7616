// rgbd-vocabulary -o VOCABULARY.txt INPUT...: builds the bag of binary words the SLAM mode finds
// loop candidates with ([Slam] vocabulary), from the ORB features ([ORB] of --config) of every
// --every-th frame of the inputs (TUM folders, rawlogs, .oni files).
#include <mrpt/config/CConfigFileMemory.h>
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <vector>

#include "rgbd_cli/CommandLine.h"
#include "rgbd_core/Config.h"
#include "rgbd_core/Interrupt.h"
#include "rgbd_core/JobPaths.h"
#include "rgbd_core/OutputFile.h"
#include "rgbd_core/Progress.h"
#include "rgbd_core/RgbdImage.h"
#include "rgbd_io/openFrameSource.h"
#include "rgbd_odometry/OrbFeatures.h"
#include "rgbd_slam/Vocabulary.h"

int main(int argc, char** argv) {
  hrgbd::CommandLine cmd("rgbd-vocabulary",
                         "ORB vocabulary (bag of binary words) for the SLAM mode's loop search");
  TCLAP::UnlabeledMultiArg<std::string> in("input", "TUM folders, rawlogs or .oni files", true,
                                           "INPUT", cmd);
  TCLAP::ValueArg<std::string> out("o", "output", "vocabulary file to write", true, "",
                                   "VOCABULARY.txt", cmd);
  TCLAP::ValueArg<std::string> cfg("c", "config", "INI file ([ORB], [TumSource] sections)", false,
                                   "", "FILE.ini", cmd);
  TCLAP::ValueArg<int> words("", "words", "number of words (default 1000)", false, 1000, "N", cmd);
  TCLAP::ValueArg<int> every("", "every", "use every N-th frame (default 5)", false, 5, "N", cmd);
  TCLAP::SwitchArg quiet("q", "quiet", "no progress line", cmd);
  return cmd.run(argc, argv, [&] {
    if (words.getValue() < 2) throw hrgbd::UsageError("--words must be at least 2");
    if (every.getValue() < 1) throw hrgbd::UsageError("--every must be at least 1");
    if (out.getValue().empty()) throw hrgbd::UsageError("--output is empty");
    std::unique_ptr<mrpt::config::CConfigFileBase> ini =
        std::make_unique<mrpt::config::CConfigFileMemory>();
    if (!cfg.getValue().empty()) ini = hrgbd::loadIniFile(cfg.getValue());
    hrgbd::rejectUnknownSections(*ini);
    hrgbd::OrbParams orb;
    orb.loadFromConfigFile(*ini, "ORB");
    std::vector<hrgbd::JobPath> inputs{{cfg.getValue(), "the configuration file (--config)"}};
    std::vector<std::unique_ptr<hrgbd::FrameSource>> sources;
    for (const auto& name : in.getValue()) {
      sources.push_back(hrgbd::openFrameSource(name, *ini));
      for (const auto& p : sources.back()->inputs()) inputs.push_back(p);
    }
    hrgbd::checkJobPaths(inputs, {{out.getValue(), "the vocabulary (--output)", false, true}});
    // the output is made now (a folder that cannot take it fails before the work) and moved into
    // place only when complete
    hrgbd::OutputFile file(out.getValue(), "vocabulary");
    // the vocabulary on stdout: the messages go to stderr, not into it
    std::ostream& log = hrgbd::writesStandardOutput({out.getValue()}) ? std::cerr : std::cout;
    cv::Mat descriptors;
    std::vector<int> image;
    int images = 0;
    for (auto& src : sources) {
      log << src->describe() << "\n";
      hrgbd::ProgressParams pp;
      pp.total = src->frameCount();
      pp.terminal = isatty(STDERR_FILENO);
      hrgbd::Progress progress(std::cerr, pp);
      std::size_t n = 0;
      while (auto obs = src->next()) {
        hrgbd::checkInterrupt();
        if (n++ % static_cast<std::size_t>(every.getValue()) == 0) {
          const auto f = hrgbd::extractOrbFeatures(hrgbd::prepareRgbdImage(*obs), orb);
          descriptors.push_back(f.descriptors);
          image.insert(image.end(), static_cast<std::size_t>(f.descriptors.rows), images++);
        }
        if (!quiet.getValue()) progress.update(n);
      }
      if (!quiet.getValue()) progress.finish();
    }
    log << descriptors.rows << " ORB descriptors from " << images << " frames\n";
    if (descriptors.rows < words.getValue())
      throw std::runtime_error("too few descriptors for " + std::to_string(words.getValue()) +
                               " words: give more frames (--every, inputs) or fewer --words");
    hrgbd::VocabularyTraining t;
    t.words = words.getValue();
    log << "clustering into " << t.words << " words" << std::endl;
    hrgbd::StagedProgress stages(std::cerr, isatty(STDERR_FILENO));
    t.progress = [&](const std::string& stage, const std::string& unit, std::size_t done,
                     std::size_t total) {
      hrgbd::checkInterrupt();
      if (!quiet.getValue()) stages.update(stage, unit, done, total);
    };
    hrgbd::Vocabulary::train(descriptors, image, t).save(file.writePath());
    stages.finish();
    file.commit();
    log << "wrote " << t.words << " words to " << out.getValue() << "\n";
    if (&log == &std::cout)  // a file (the path is absolute: an INI's are relative to it)
      log << "to use it, put these lines in the INI file (--config) of hybrid-rgbd-odometry or "
             "rgbd-live:\n[Slam]\nvocabulary = "
          << std::filesystem::absolute(out.getValue()).lexically_normal().string() << "\n";
  });
}
