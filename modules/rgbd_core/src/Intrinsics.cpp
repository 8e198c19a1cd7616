#include "rgbd_core/Intrinsics.h"

#include <algorithm>
#include <regex>
#include <stdexcept>

namespace hrgbd {

mrpt::img::TCamera pinholeCamera(double fx, double fy, double cx, double cy, unsigned width,
                                 unsigned height) {
  mrpt::img::TCamera cam;
  cam.ncols = width;
  cam.nrows = height;
  cam.intrinsicParams.setZero();
  cam.intrinsicParams(0, 0) = fx;
  cam.intrinsicParams(1, 1) = fy;
  cam.intrinsicParams(0, 2) = cx;
  cam.intrinsicParams(1, 2) = cy;
  cam.intrinsicParams(2, 2) = 1.0;
  cam.distortion = mrpt::img::DistortionModel::none;
  cam.dist.fill(0.0);
  return cam;
}

mrpt::img::TCamera intrinsicsPreset(const std::string& name) {
  // Values from the TUM RGB-D benchmark's camera calibration page (see shared/data/README.md).
  auto withDistortion = [](mrpt::img::TCamera cam, double k1, double k2, double p1, double p2,
                           double k3) {
    cam.distortion = mrpt::img::DistortionModel::plumb_bob;
    cam.dist = {k1, k2, p1, p2, k3, 0.0, 0.0, 0.0};
    return cam;
  };
  if (name == "fr1")
    return withDistortion(pinholeCamera(517.3, 516.5, 318.6, 255.3), 0.2624, -0.9531, -0.0054,
                          0.0026, 1.1633);
  if (name == "fr2")
    return withDistortion(pinholeCamera(520.9, 521.0, 325.1, 249.7), 0.2312, -0.7849, -0.0033,
                          -0.0001, 0.9172);
  if (name == "fr3") return pinholeCamera(535.4, 539.2, 320.1, 247.6);
  if (name == "ros_default") return pinholeCamera(525.0, 525.0, 319.5, 239.5);
  throw std::invalid_argument("unknown intrinsics preset '" + name +
                              "' (known: fr1, fr2, fr3, ros_default)");
}

std::string guessTumPreset(const std::string& path) {
  std::string p = path;
  std::transform(p.begin(), p.end(), p.begin(), ::tolower);
  // "fr" or "freiburg" starting a word ("afr1" is not a camera), the digit ending one
  static const std::regex re("(^|[^a-z])(freiburg|fr)([123])([^0-9]|$)");
  // The deepest path component that names a camera: the folder's own name before its parents'
  // ("runs_fr1/rgbd_dataset_freiburg3_teddy" is fr3).
  std::size_t end = p.size();
  while (end > 0) {
    const std::size_t slash = p.find_last_of("/\\", end - 1);
    const std::size_t begin = slash == std::string::npos ? 0 : slash + 1;
    const std::string component = p.substr(begin, end - begin);
    std::smatch m;
    if (std::regex_search(component, m, re)) return "fr" + m[3].str();
    if (slash == std::string::npos) break;
    end = slash;
  }
  return "";
}

}  // namespace hrgbd
