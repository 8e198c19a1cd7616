#include "rgbd_io/TumSource.h"

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/system/filesystem.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <opencv2/imgcodecs.hpp>
#include <set>
#include <stdexcept>
#include <tuple>

#include "ImageFiles.h"
#include "rgbd_core/Config.h"
#include "rgbd_core/Intrinsics.h"
#include "rgbd_core/RgbdFrame.h"
#include "rgbd_core/TextFile.h"
#include "rgbd_core/Timestamp.h"

namespace hrgbd {
namespace {

std::string sizeText(cv::Size s) {
  return std::to_string(s.width) + "x" + std::to_string(s.height);
}

cv::Mat readImage(const std::string& path, const char* what, int flags) {
  requireRegularFile(path, std::string(what) + " image");  // a folder, /dev/zero, a FIFO
  refuseHugePng(path);
  refuseTruncatedJpeg(path, what);
  cv::Mat m;
  try {
    m = cv::imread(path, flags);
  } catch (const cv::Exception& e) {  // e.g. a JPEG declaring more pixels than OpenCV allows
    throw std::runtime_error(std::string("cannot read ") + what + " image '" + path +
                             "': " + e.err);
  }
  if (m.empty())
    throw std::runtime_error(std::string("cannot read ") + what + " image '" + path + "'");
  if (std::int64_t(m.cols) * m.rows > kMaxPixels)
    throw std::runtime_error(std::string(what) + " image '" + path + "' is " + sizeText(m.size()) +
                             ", more than the " + std::to_string(kMaxPixels) +
                             " pixels accepted for one frame");
  return m;
}

// Depth must be what TUM writes: one channel of 16-bit values (value / depth_factor = metres).
// Anything else is refused rather than converted: OpenCV would turn a colour PNG into grey
// levels and an 8-bit one into small depths, both read as plausible but wrong metres.
void requireDepthFormat(const cv::Mat& depth, const std::string& path) {
  if (depth.type() == CV_16UC1) return;
  const int bits = depth.depth() == CV_8U || depth.depth() == CV_8S     ? 8
                   : depth.depth() == CV_16U || depth.depth() == CV_16S ? 16
                   : depth.depth() == CV_64F                            ? 64
                                                                        : 32;
  const bool real = depth.depth() == CV_32F || depth.depth() == CV_64F;
  throw std::runtime_error(
      "depth image '" + path + "' is " + std::to_string(depth.channels()) + "-channel " +
      std::to_string(bits) + "-bit" + (real ? " floating point" : "") +
      "; depth must be a single-channel 16-bit image (value / [TumSource] depth_factor = metres)");
}

// Says `text` on stderr once per folder and process (a benchmark opens a folder per method).
void warnOnce(const std::string& folder, const std::string& text) {
  static std::mutex mutex;
  static std::set<std::string> warned;
  const std::lock_guard<std::mutex> lock(mutex);
  if (warned.insert(mrpt::system::toAbsolutePath(folder)).second) std::cerr << text << std::endl;
}

}  // namespace

TumSource::TumSource(const std::string& folder, const TumSourceParams& params)
    : m_folder(folder), m_params(params) {
  if (!mrpt::system::directoryExists(folder))
    throw std::runtime_error(
        "TUM folder '" + folder + "' " +
        (mrpt::system::fileExists(folder) ? "is a file, not a folder" : "does not exist"));
  const auto rgb = parseTumList(folder + "/rgb.txt");
  const auto depth = parseTumList(folder + "/depth.txt");
  if (rgb.empty()) throw std::runtime_error("'" + folder + "/rgb.txt' lists no images");
  m_pairs = associateTumLists(rgb, depth, params.max_time_difference);
  m_unmatched_rgb = rgb.size() - m_pairs.size();
  if (m_pairs.empty())
    throw std::runtime_error("'" + folder + "': no colour/depth pair closer than " +
                             std::to_string(params.max_time_difference) + " s");

  // Explicit intrinsics (the INI's or the folder's calibration.txt) are in pixels of the folder's
  // own images: their size is the first frame's (0 x 0 until it is read).
  m_camera_name = params.intrinsics;
  const auto calibration = folder + "/calibration.txt";
  const bool has_calibration =
      std::filesystem::is_symlink(calibration) || std::filesystem::exists(calibration);
  if (m_camera_name == "auto" && has_calibration) {
    // The folder says its camera (ETH3D's RGB-D folders, rgbd-simulate --tum): no guess.
    if (!std::filesystem::exists(calibration))
      throw std::runtime_error("'" + calibration + "' is a broken symbolic link");
    const auto c =
        parseTumCalibrationText(readTextFile(calibration, "TUM calibration"), calibration);
    m_camera = pinholeCamera(c.fx, c.fy, c.cx, c.cy, 0, 0);
    m_camera_name = "calibration.txt";  // checkExplicitCamera() names the file by this
    m_camera_origin = " (the folder's own: fx " + formatSeconds(c.fx) + ", fy " +
                      formatSeconds(c.fy) + ", cx " + formatSeconds(c.cx) + ", cy " +
                      formatSeconds(c.cy) +
                      "; no lens distortion or rolling shutter; [TumSource] intrinsics other "
                      "than auto overrides it)";
  } else if (m_camera_name == "auto") {
    // normalised: "..", run from inside a folder named for a camera, names its parent
    m_camera_name = guessTumPreset(std::filesystem::absolute(folder).lexically_normal().string());
    if (m_camera_name.empty()) {
      m_camera_name = "ros_default";
      m_camera_origin = " (guessed: the folder's path names no Freiburg camera)";
      // Said when the first frame is read: a run refused for its options prints its error alone.
      m_intrinsics_warning =
          "warning: TUM folder '" + folder +
          "': its path names no Freiburg camera (freiburg1/2/3 or fr1/2/3), so the intrinsics "
          "are ros_default (fx = fy = 525, cx = 319.5, cy = 239.5 at 640x480); if they are not "
          "this camera's, write them to the folder's calibration.txt as 'fx fy cx cy', or set "
          "[TumSource] intrinsics = fr1|fr2|fr3|ros_default, or explicit with fx, fy, cx, cy, in "
          "an INI file given with --config";
    } else {
      m_camera_origin = " (chosen by the folder's path; [TumSource] intrinsics sets them)";
    }
    m_camera = intrinsicsPreset(m_camera_name);
  } else {
    m_camera = m_camera_name == "explicit"
                   ? pinholeCamera(params.fx, params.fy, params.cx, params.cy, 0, 0)
                   : intrinsicsPreset(m_camera_name);
    if (has_calibration)
      m_camera_origin = " ([TumSource] intrinsics; the folder's calibration.txt is not read)";
  }

  const auto gt = folder + "/groundtruth.txt";
  if (mrpt::system::fileExists(gt)) m_ground_truth = loadTumTrajectory(gt);

  // What no output may overwrite: the lists, the ground truth, the calibration (read or not), the
  // association lists TUM's associate.py writes (associat*.txt) and every image listed, paired or
  // not.
  for (const auto* name : {"rgb.txt", "depth.txt", "groundtruth.txt", "calibration.txt"})
    m_inputs.push_back({folder + "/" + name, std::string("the TUM folder's ") + name});
  std::error_code ec;
  for (const auto& f : std::filesystem::directory_iterator(folder, ec)) {
    const auto name = f.path().filename().string();
    if (name.rfind("associat", 0) == 0 && f.path().extension() == ".txt")
      m_inputs.push_back({f.path().string(), "the TUM folder's " + name});
  }
  // The folders holding the images (rgb/, depth/) are inputs as folders: nothing may be written
  // inside them either (a new file there is no listed image, but it is the dataset's folder).
  std::set<std::string> image_folders;
  for (const auto* list : {&rgb, &depth})
    for (const auto& e : *list) {
      m_inputs.push_back({imagePath(e.file), "the TUM folder's image " + e.file});
      const auto parent = std::filesystem::path(imagePath(e.file)).parent_path();
      if (image_folders.insert(parent.string()).second &&  // each folder once, not per image
          !std::filesystem::equivalent(parent, folder, ec))
        m_inputs.push_back(
            {parent.string(),
             "the TUM folder's image folder '" + parent.lexically_relative(folder).string() + "'",
             true});
    }
}

mrpt::obs::CObservation3DRangeScan::Ptr TumSource::next() {
  if (m_next >= m_pairs.size()) return nullptr;
  if (!m_intrinsics_warning.empty()) warnOnce(m_folder, m_intrinsics_warning);
  m_intrinsics_warning.clear();
  const auto& p = m_pairs[m_next++];
  const auto rgb_path = imagePath(p.rgb.file);
  const auto depth_path = imagePath(p.depth.file);
  const cv::Mat bgr = readImage(rgb_path, "colour", cv::IMREAD_COLOR);
  const cv::Mat depth = readImage(depth_path, "depth", cv::IMREAD_UNCHANGED);
  requireDepthFormat(depth, depth_path);
  if (bgr.size() != depth.size())
    throw std::runtime_error("'" + rgb_path + "' is " + sizeText(bgr.size()) + " but '" +
                             depth_path + "' is " + sizeText(depth.size()) +
                             "; colour and depth images must have one size");
  if (m_first_size.empty()) {
    // explicit intrinsics: checked once, every frame has this size
    if (m_camera.ncols == 0) checkExplicitCamera(m_camera, depth.size(), rgb_path);
    m_first_size = depth.size();
    m_first_file = rgb_path;
  } else if (depth.size() != m_first_size) {
    throw std::runtime_error("'" + rgb_path + "' (frame " + std::to_string(m_next - 1) + ") is " +
                             sizeText(depth.size()) + " but the sequence's first frame '" +
                             m_first_file + "' is " + sizeText(m_first_size) +
                             "; all frames of a sequence must have one size");
  }
  ++m_stats.frames;
  return makeRgbdObservation(bgr, depth, 1.0 / m_params.depth_factor,
                             cameraFor(depth.size(), rgb_path), p.rgb.stamp);
}

std::string TumSource::imagePath(const std::string& file) const {
  // TUM lists name images relative to the folder; an absolute path is taken as it is.
  return std::filesystem::path(file).is_absolute() ? file : m_folder + "/" + file;
}

mrpt::img::TCamera TumSource::cameraFor(cv::Size size, const std::string& file) const {
  auto cam = m_camera;
  if (cam.ncols == 0) {  // explicit: for the images as they are
    cam.ncols = size.width;
    cam.nrows = size.height;
    return cam;
  }
  if (size.width == int(cam.ncols) && size.height == int(cam.nrows)) return cam;
  // A preset is calibrated at 640x480; another size of that aspect ratio is the same sensor
  // binned or upsampled (MRPT's scaleToResolution), any other aspect ratio is another camera.
  if (std::int64_t(size.width) * cam.nrows != std::int64_t(size.height) * cam.ncols)
    throw std::runtime_error(
        "'" + file + "' is " + sizeText(size) + " but the intrinsics " + m_camera_name +
        " are for " + std::to_string(cam.ncols) + "x" + std::to_string(cam.nrows) +
        " images and cannot be scaled to another aspect ratio; give this camera's intrinsics: "
        "[TumSource] intrinsics = explicit with fx, fy, cx, cy in pixels of these images");
  cam.scaleToResolution(size.width, size.height);
  return cam;
}

void TumSource::checkExplicitCamera(const mrpt::img::TCamera& cam, cv::Size size,
                                    const std::string& file) const {
  const auto origin = m_camera_name == "calibration.txt" ? "'" + m_folder + "/calibration.txt': "
                                                         : std::string("[TumSource] ");
  // A principal point off the image, or a focal length no pinhole lens has (a field of view
  // wider than 169 or narrower than 3 degrees), is a value meant for other images, or a typo.
  // They ran, every frame "ok" on a wrong camera.
  for (const auto& [key, value, extent] :
       {std::tuple{"cx", cam.cx(), size.width}, std::tuple{"cy", cam.cy(), size.height}})
    if (!(value >= 0 && value <= extent))
      throw std::runtime_error(origin + key + " = " + formatSeconds(value) + " lies outside the " +
                               sizeText(size) + " image '" + file +
                               "'; the principal point is in pixels of the folder's images");
  for (const auto& [key, value, extent] :
       {std::tuple{"fx", cam.fx(), size.width}, std::tuple{"fy", cam.fy(), size.height}})
    if (!(value >= extent / 20.0 && value <= extent * 20.0))
      throw std::runtime_error(origin + key + " = " + formatSeconds(value) +
                               " is no focal length for the " + sizeText(size) + " image '" + file +
                               "' (it must lie between 1/20 and 20 times the image's " +
                               (key[1] == 'x' ? "width" : "height") + ")");
  // Values for twice or half the image size put the principal point a quarter of the image off
  // its centre; a real camera's lies near it. Said, not refused: a cropped image is off-centre.
  const double off_x = std::abs(cam.cx() - (size.width - 1) / 2.0) / size.width;
  const double off_y = std::abs(cam.cy() - (size.height - 1) / 2.0) / size.height;
  if (std::max(off_x, off_y) > 1.0 / 6)
    warnOnce(m_folder, "warning: " + origin + "the principal point (" + formatSeconds(cam.cx()) +
                           ", " + formatSeconds(cam.cy()) + ") lies more than a sixth of the " +
                           sizeText(size) + " image '" + file +
                           "' off its centre: are these intrinsics for another image size?");
}

std::string TumSource::describe() const {
  return "TUM folder '" + m_folder + "': " + std::to_string(m_pairs.size()) + " frames (" +
         std::to_string(m_unmatched_rgb) + " colour images without depth), intrinsics " +
         m_camera_name + m_camera_origin + ", " + std::to_string(m_ground_truth.size()) +
         " ground-truth poses";
}

double TumSource::rollingShutterMs() const {
  // fr3's slow sequences measured no consistent gain (doc/measurements.md): not undone there
  const bool fast_kinect = m_camera_name == "fr1" || m_camera_name == "fr2";
  return fast_kinect ? m_params.rolling_shutter_ms : 0;
}

}  // namespace hrgbd
