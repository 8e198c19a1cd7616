// rgbd-simulate: renders a simulated RGB-D sequence with exact ground truth.
#include <mrpt/config/CConfigFileMemory.h>
#include <unistd.h>

#include <iomanip>
#include <iostream>
#include <sstream>

#include "rgbd_cli/CommandLine.h"
#include "rgbd_core/Config.h"
#include "rgbd_core/JobPaths.h"
#include "rgbd_io/RawlogSource.h"
#include "rgbd_io/RawlogWriter.h"
#include "rgbd_sim/Scene.h"
#include "rgbd_sim/Simulator.h"

namespace {
using Ini = mrpt::config::CConfigFileMemory;

/** Writes option `a` to the [Simulator] key of the same name when it was given, or `always`
 * (without an INI file, the command line's defaults are the simulator's). */
template <class T>
void put(Ini& ini, TCLAP::ValueArg<T>& a, bool always) {
  if (always || a.isSet()) ini.write("Simulator", a.getName(), a.getValue());
}

/** Copies the [Simulator] section of the INI file `path` into `ini`; refuses unknown sections. */
void copySimulatorSection(const std::string& path, Ini& ini) {
  const auto file = hrgbd::loadIniFile(path);
  hrgbd::rejectUnknownSections(*file);  // the other sections' keys are their readers' to check
  std::vector<std::string> keys;
  file->getAllKeys("Simulator", keys);
  for (const auto& k : keys) ini.write("Simulator", k, file->read_string("Simulator", k, ""));
}

/** `p` as the [Simulator] section of an INI file. */
std::string iniText(const hrgbd::sim::SimParams& p) {
  Ini out;
  p.saveToConfigFile(out, "Simulator");
  return out.getContent();
}

/** What was rendered, how fast, and the files written (a TUM folder as one). */
std::string summary(const hrgbd::sim::SimParams& p, const hrgbd::sim::SimResult& r,
                    const hrgbd::sim::SimOutputs& outputs) {
  std::ostringstream s;
  s << "rendered " << r.frames << " frames of scene " << p.scene
    << (p.far ? " (far, ~2 m)" : " (near, ~1 m)") << ", median " << std::fixed
    << std::setprecision(1) << r.ms_per_frame << " ms/frame (" << 1000.0 / r.ms_per_frame
    << " frames/s)\n";
  const auto in_tum = [&](const std::string& path) {
    return !outputs.tum_folder.empty() && path.rfind(outputs.tum_folder + "/", 0) == 0;
  };
  for (const auto& f : hrgbd::sim::writtenFiles(outputs))
    if (!f.path.empty() && !in_tum(f.path))
      s << "written: " << f.path << (f.folder ? "/" : "") << "\n";
  if (!outputs.tum_folder.empty())
    s << "written: " << outputs.tum_folder
      << "/ (TUM folder: rgb/, depth/, rgb.txt, depth.txt, groundtruth.txt, calibration.txt)\n";
  return s.str();
}

/** Frames that see little of the scene, or nothing. */
std::string sparseDepthWarning(const hrgbd::sim::SimParams& p, const hrgbd::sim::SimResult& r) {
  if (r.sparse_depth_frames == 0) return "";
  std::ostringstream s;
  s << "warning: " << r.sparse_depth_frames << " of " << r.frames
    << " frames have depth on under a quarter of the image: the camera looks past the scene"
    << (hrgbd::sim::isProceduralMotion(p.motion) ? "" : " (the motion file leaves it)") << "\n";
  return s.str();
}
}  // namespace

int main(int argc, char** argv) {
  using TCLAP::ValueArg;
  hrgbd::CommandLine cmd("rgbd-simulate", "Kinect-like RGB-D sequences with ground truth");
  ValueArg<std::string> scene("s", "scene", "scene type (desk)", false, "desk",
                              cmd.oneOf(hrgbd::sim::sceneTypes()), cmd);
  TCLAP::SwitchArg far("", "far", "camera at ~2 m instead of ~1 m", cmd);
  ValueArg<int> frames("n", "frames", "number of frames (30)", false, 30, cmd.atLeast(1, "N"), cmd);
  ValueArg<int> seed("", "seed", "noise seed (1)", false, 1, "SEED", cmd);
  ValueArg<std::string> motion("", "motion", "sweep, loop, or a TUM trajectory to replay", false,
                               "sweep", "FILE", cmd);
  ValueArg<double> walker("", "walker-speed",
                          "[m/s] a person-sized box walks across the scene (0: none; at most 10)",
                          false, 0, cmd.atLeast(0.0, "M/S"), cmd);
  ValueArg<std::string> rawlog("o", "rawlog", "output rawlog", false, "", "OUT.rawlog", cmd);
  ValueArg<std::string> tum("", "tum", "output TUM folder", false, "", "FOLDER", cmd);
  ValueArg<std::string> oni("", "oni", "output OpenNI recording", false, "", "OUT.oni", cmd);
  ValueArg<std::string> config("c", "config",
                               "INI file whose [Simulator] section sets the scene and the sensor "
                               "model; the options given here override its keys",
                               false, "", "FILE.ini", cmd);
  TCLAP::SwitchArg print("", "print-config", "print the effective [Simulator] section", cmd);
  ValueArg<std::string> images("", "images", "colour storage in the rawlog (inline)", false,
                               "inline", cmd.oneOf<hrgbd::ImageStorage>(), cmd);
  TCLAP::SwitchArg quiet("q", "quiet", "no progress line", cmd);
  return cmd.run(argc, argv, [&] {
    Ini ini;
    if (config.isSet()) copySimulatorSection(config.getValue(), ini);
    for (auto* a : {&scene, &motion}) put(ini, *a, !config.isSet());
    for (auto* a : {&frames, &seed}) put(ini, *a, !config.isSet());
    if (walker.isSet() || !config.isSet())  // the option's name has a hyphen, the key not
      ini.write("Simulator", "walker_speed", walker.getValue());
    if (far.isSet()) ini.write("Simulator", "far", "true");
    hrgbd::sim::SimParams p;
    p.loadFromConfigFile(ini, "Simulator");
    if (print.isSet()) {
      std::cout << iniText(p);
      return;
    }
    if (rawlog.getValue().empty() && tum.getValue().empty() && oni.getValue().empty())
      throw hrgbd::UsageError("give --rawlog, --tum and/or --oni");
    const hrgbd::sim::SimOutputs outputs{
        rawlog.getValue(), tum.getValue(),
        hrgbd::parseEnum<hrgbd::ImageStorage>(images.getValue(), "command line", "images"),
        oni.getValue()};
    if (!tum.getValue().empty()) hrgbd::sim::checkTumOutputFolder(tum.getValue());
    hrgbd::checkJobPaths(
        {{config.getValue(), "the configuration file (--config)"},
         {hrgbd::sim::isProceduralMotion(p.motion) ? "" : p.motion,
          motion.isSet() ? "the motion file (--motion)" : "the motion file ([Simulator] motion)"}},
        hrgbd::sim::writtenFiles(outputs));
    hrgbd::ProgressParams pp;
    pp.total = static_cast<std::size_t>(p.frames);
    pp.terminal = isatty(STDERR_FILENO);
    hrgbd::Progress progress(std::cerr, pp);
    const auto r = hrgbd::sim::simulate(p, outputs, quiet.getValue() ? nullptr : &progress);
    if (!quiet.getValue()) progress.finish();
    // a rawlog or recording on stdout: the summary goes to stderr, not into it
    const bool on_stdout = hrgbd::writesStandardOutput({rawlog.getValue(), oni.getValue()});
    (on_stdout ? std::cerr : std::cout) << summary(p, r, outputs);
    for (const auto& o : {rawlog.getValue(), oni.getValue()})
      if (!o.empty() && hrgbd::groundTruthOutputFor(o).empty())
        std::cerr << "rgbd-simulate: note: the ground truth is not written: '" << o
                  << "' is not a regular file, so no <name>_groundtruth.txt goes beside it\n";
    std::cerr << sparseDepthWarning(p, r);
  });
}
