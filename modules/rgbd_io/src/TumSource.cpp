#include "rgbd_io/TumSource.h"

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/system/filesystem.h>

#include <algorithm>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "rgbd_core/Config.h"
#include "rgbd_core/Intrinsics.h"
#include "rgbd_core/RgbdFrame.h"

namespace hrgbd {

TumSource::TumSource(const std::string& folder, const TumSourceParams& params)
    : m_folder(folder), m_params(params) {
  if (!mrpt::system::directoryExists(folder))
    throw std::runtime_error("TUM folder '" + folder + "' does not exist");
  const auto rgb = parseTumList(folder + "/rgb.txt");
  const auto depth = parseTumList(folder + "/depth.txt");
  if (rgb.empty()) throw std::runtime_error("'" + folder + "/rgb.txt' lists no images");
  m_pairs = associateTumLists(rgb, depth, params.max_time_difference);
  m_unmatched_rgb = rgb.size() - m_pairs.size();
  if (m_pairs.empty())
    throw std::runtime_error("'" + folder + "': no colour/depth pair closer than " +
                             std::to_string(params.max_time_difference) + " s");

  m_camera_name = params.intrinsics;
  if (m_camera_name == "auto") {
    m_camera_name = guessTumPreset(mrpt::system::toAbsolutePath(folder));
    if (m_camera_name.empty()) m_camera_name = "ros_default";
  }
  m_camera = m_camera_name == "explicit" ? pinholeCamera(params.fx, params.fy, params.cx, params.cy)
                                         : intrinsicsPreset(m_camera_name);

  const auto gt = folder + "/groundtruth.txt";
  if (mrpt::system::fileExists(gt)) m_ground_truth = loadTumTrajectory(gt);

  // What no output may overwrite: the lists, the ground truth, the association lists TUM's
  // associate.py writes (associat*.txt) and every image listed, paired or not.
  for (const auto* name : {"rgb.txt", "depth.txt", "groundtruth.txt"})
    m_inputs.push_back({folder + "/" + name, std::string("the TUM folder's ") + name});
  std::error_code ec;
  for (const auto& f : std::filesystem::directory_iterator(folder, ec)) {
    const auto name = f.path().filename().string();
    if (name.rfind("associat", 0) == 0 && f.path().extension() == ".txt")
      m_inputs.push_back({f.path().string(), "the TUM folder's " + name});
  }
  for (const auto* list : {&rgb, &depth})
    for (const auto& e : *list)
      m_inputs.push_back({folder + "/" + e.file, "the TUM folder's image " + e.file});
}

mrpt::obs::CObservation3DRangeScan::Ptr TumSource::next() {
  if (m_next >= m_pairs.size()) return nullptr;
  const auto& p = m_pairs[m_next++];
  const auto rgb_path = m_folder + "/" + p.rgb.file;
  const auto depth_path = m_folder + "/" + p.depth.file;
  cv::Mat bgr = cv::imread(rgb_path, cv::IMREAD_COLOR);
  if (bgr.empty()) throw std::runtime_error("cannot read colour image '" + rgb_path + "'");
  cv::Mat depth = cv::imread(depth_path, cv::IMREAD_ANYDEPTH);
  if (depth.empty()) throw std::runtime_error("cannot read depth image '" + depth_path + "'");
  if (depth.type() != CV_16UC1)
    throw std::runtime_error("depth image '" + depth_path + "' is not a 16-bit PNG");
  if (bgr.size() != depth.size())
    throw std::runtime_error("'" + rgb_path + "' and '" + depth_path + "' differ in size");
  auto cam = m_camera;
  if (depth.cols != static_cast<int>(cam.ncols) || depth.rows != static_cast<int>(cam.nrows))
    cam.scaleToResolution(depth.cols, depth.rows);
  ++m_stats.frames;
  return makeRgbdObservation(bgr, depth, 1.0 / m_params.depth_factor, cam, p.rgb.stamp);
}

std::string TumSource::describe() const {
  return "TUM folder '" + m_folder + "': " + std::to_string(m_pairs.size()) + " frames (" +
         std::to_string(m_unmatched_rgb) + " colour images without depth), intrinsics " +
         m_camera_name + ", " + std::to_string(m_ground_truth.size()) + " ground-truth poses";
}

}  // namespace hrgbd
