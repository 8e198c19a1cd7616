// Fuzz target: the TUM text formats. The input is read as a list file (rgb.txt / depth.txt),
// associated with itself, as a trajectory (groundtruth.txt) and as a calibration.txt. Every reader
// must either succeed or throw std::runtime_error (its messages name the file and line); anything
// else, a crash or a non-finite value accepted, is a bug.
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "FuzzUtil.h"
#include "rgbd_core/Trajectory.h"
#include "rgbd_io/TumLists.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const auto list = hrgbd::parseTumListText(text, "fuzz.txt");
    for (const auto& e : list)
      if (!std::isfinite(e.t)) std::abort();
    hrgbd::associateTumLists(list, list, 0.02);
  } catch (const std::runtime_error&) {
  }
  try {
    const auto c = hrgbd::parseTumCalibrationText(text, "calibration.txt");
    for (const double v : {c.fx, c.fy, c.cx, c.cy})
      if (!std::isfinite(v)) std::abort();
    if (!(c.fx > 0 && c.fy > 0)) std::abort();
  } catch (const std::runtime_error&) {
  }
  static const auto path = hrgbd::fuzz::tempPath("groundtruth.txt");
  hrgbd::fuzz::writeFile(path, data, size);
  try {
    for (const auto& p : hrgbd::loadTumTrajectory(path)) {
      const auto& pose = p.pose;
      if (!std::isfinite(p.t) || !std::isfinite(pose.x()) || !std::isfinite(pose.y()) ||
          !std::isfinite(pose.z()) || !std::isfinite(pose.yaw()) || !std::isfinite(pose.pitch()) ||
          !std::isfinite(pose.roll()))
        std::abort();
    }
  } catch (const std::runtime_error&) {
  }
  return 0;
}
