#include "rgbd_io/RawlogSource.h"

#include <mrpt/img/CImage.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/system/filesystem.h>

#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "ImageFiles.h"
#include "ReadGuards.h"
#include "rgbd_core/ErrorText.h"
#include "rgbd_core/TextFile.h"
#include "rgbd_core/Timestamp.h"

namespace hrgbd {
namespace {

// MRPT deserialises bool fields by reading a raw byte into them: a corrupt byte leaves a bool
// that is neither true nor false, and reading it is undefined behaviour (found by fuzz_rawlog).
void normaliseFlags(mrpt::obs::CObservation3DRangeScan& o) {
  for (bool* b : {&o.hasPoints3D, &o.hasRangeImage, &o.range_is_depth, &o.hasIntensityImage,
                  &o.hasConfidenceImage}) {
    unsigned char byte = 0;
    std::memcpy(&byte, b, 1);
    *b = byte != 0;
  }
}

std::uintmax_t fileSize(const std::string& path) {
  std::error_code ec;
  const auto n = std::filesystem::file_size(path, ec);
  return ec ? 0 : n;
}

}  // namespace

std::string groundTruthPathFor(const std::string& rawlog_path) {
  return std::filesystem::path(rawlog_path).replace_extension().string() + "_groundtruth.txt";
}

std::string groundTruthOutputFor(const std::string& output) {
  // /dev/stdout redirected to a file resolves to that file: the name decides too
  const auto name = std::filesystem::absolute(output).lexically_normal().string();
  if (name.rfind("/dev/", 0) == 0 || name.rfind("/proc/", 0) == 0) return "";
  const auto kind = specialFileKind(output);
  return kind.empty() || kind == "a folder" ? groundTruthPathFor(output) : "";
}

RawlogSource::RawlogSource(const std::string& path) : m_path(path) {
  installReadGuards();
  if (!mrpt::system::fileExists(path))
    throw std::runtime_error("rawlog '" + path + "' does not exist");
  // A FIFO would be read up to its end by the frame count before the run, and /dev/zero without
  // end; MRPT's own message for either names no file.
  requireRegularFile(path, "rawlog",
                     "a rawlog is read twice (its frames counted, then played): give a file");
  if (!m_file.open(path)) throw std::runtime_error("cannot open rawlog '" + path + "'");
  m_archive =
      std::make_unique<mrpt::serialization::CArchiveStreamBase<mrpt::io::CFileGZInputStream>>(
          m_file);
  // "<stem>_Images" first: MRPT 2.5's detectImagesDirectory() misses it for absolute paths.
  const auto own = std::filesystem::path(path).replace_extension().string() + "_Images";
  m_images_dir =
      std::filesystem::is_directory(own) ? own : mrpt::obs::CRawlog::detectImagesDirectory(path);
  // When neither exists, MRPT's guess can be a path nobody wrote ("/tmpImages" for "/tmp/x"):
  // the messages name the folder a rawlog's images belong in.
  if (!std::filesystem::is_directory(m_images_dir)) m_images_dir = own;
  const auto gt = groundTruthPathFor(path);
  if (mrpt::system::fileExists(gt)) m_ground_truth = loadTumTrajectory(gt);
}

mrpt::obs::CObservation3DRangeScan::Ptr RawlogSource::next() {
  using mrpt::obs::CObservation3DRangeScan;
  while (m_pending.empty()) {
    const auto start = m_file.getPosition();
    mrpt::serialization::CSerializable::Ptr obj;
    try {
      const ReadingRawlogEntry reading;
      obj = m_archive->ReadObject();
    } catch (const mrpt::serialization::CExceptionEOF&) {
      // A clean end leaves no byte of a partial object behind. Garbage with a gzip header
      // decodes to nothing at all: an end before the first entry of a non-empty file.
      if (m_file.getPosition() == start && (m_entry > 0 || fileSize(m_path) == 0)) return nullptr;
      if (m_entry == 0)
        throw std::runtime_error("rawlog '" + m_path +
                                 "' could not be decoded: it is not an MRPT rawlog (plain or "
                                 "gzip-compressed)");
      throw std::runtime_error("rawlog '" + m_path + "' is truncated inside entry " +
                               std::to_string(m_entry) + " (at byte " + std::to_string(start) +
                               " of the uncompressed stream)");
    } catch (const std::exception& e) {
      if (m_entry == 0)
        throw std::runtime_error("rawlog '" + m_path +
                                 "' could not be decoded: it is not an MRPT rawlog (plain or "
                                 "gzip-compressed), or is corrupt at entry 0: " +
                                 errorText(e));
      throw std::runtime_error("rawlog '" + m_path + "' is corrupt at entry " +
                               std::to_string(m_entry) + ": " + errorText(e));
    }
    ++m_entry;
    if (auto obs = std::dynamic_pointer_cast<CObservation3DRangeScan>(obj)) {
      m_pending.push_back(obs);
    } else if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj)) {
      for (const auto& o : *sf) {
        if (auto o3d = std::dynamic_pointer_cast<CObservation3DRangeScan>(o))
          m_pending.push_back(o3d);
        else
          ++m_stats.skipped_objects;
      }
    } else {
      ++m_stats.skipped_objects;
    }
  }
  auto obs = m_pending.front();
  m_pending.pop_front();
  normaliseFlags(*obs);
  // the messages' start, made only for one
  auto where = [&] {
    return "rawlog '" + m_path + "' entry " + std::to_string(m_entry - 1) + ": ";
  };
  try {
    checkFrameTime(obs->timestamp);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(where() + e.what());
  }
  if (m_stats.frames == 0) m_camera = obs->sensorLabel;
  if (obs->sensorLabel != m_camera)  // two cameras' frames would be registered as one sequence
    throw std::runtime_error(where() + "a frame of camera '" + obs->sensorLabel +
                             "' after frames of camera '" + m_camera +
                             "'; the odometry follows one camera: keep its frames with "
                             "rawlog-edit --keep-label " +
                             m_camera);
  // As in TUM lists: a trajectory, its evaluation and the motion prediction need time to go on.
  if (m_stats.frames > 0 && !(obs->timestamp > m_last_time))
    throw std::runtime_error(where() + "time stamp " + formatFrameTime(obs->timestamp) +
                             " is not after the previous frame's (" + formatFrameTime(m_last_time) +
                             ", entry " + std::to_string(m_last_entry) +
                             "); the frames of a rawlog must be in strictly increasing time order");
  m_last_time = obs->timestamp;
  m_last_entry = m_entry - 1;
  if (obs->hasIntensityImage && obs->intensityImage.isExternallyStored()) {
    mrpt::img::CImage::setImagesPathBase(m_images_dir);
    const auto file = obs->intensityImage.getExternalStorageFileAbsolutePath();
    const auto folder = std::filesystem::path(file).parent_path().string();
    if (!std::filesystem::is_directory(folder))
      throw std::runtime_error("rawlog '" + m_path + "' references external images in folder '" +
                               folder + "', which does not exist (entry " +
                               std::to_string(m_entry - 1) + ", image '" +
                               obs->intensityImage.getExternalStorageFile() + "')");
    if (!mrpt::system::fileExists(file))
      throw std::runtime_error(where() + "external image '" + file + "' is missing");
    requireRegularFile(file, where() + "external image");  // a folder, a FIFO, /dev/zero
    try {
      refuseTruncatedJpeg(file, "external");
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(where() + e.what());
    }
  }
  try {
    obs->load();
  } catch (const std::exception& e) {
    throw std::runtime_error(where() + "cannot load external data: " + errorText(e));
  }
  checkSize(*obs);
  ++m_stats.frames;
  return obs;
}

void RawlogSource::checkSize(const mrpt::obs::CObservation3DRangeScan& obs) {
  // An image that disagrees with its own intrinsics is the odometry's to flag (BadInput); a
  // sequence whose frames change size cannot be registered frame to frame at all.
  cv::Size size;
  if (obs.hasRangeImage)
    size = {int(obs.rangeImage.cols()), int(obs.rangeImage.rows())};
  else if (obs.hasIntensityImage)
    size = {int(obs.intensityImage.getWidth()), int(obs.intensityImage.getHeight())};
  auto text = [](cv::Size s) { return std::to_string(s.width) + "x" + std::to_string(s.height); };
  if (m_first_size.empty()) {
    m_first_size = size;
    m_first_entry = m_entry - 1;
  } else if (!size.empty() && size != m_first_size) {
    throw std::runtime_error("rawlog '" + m_path + "' entry " + std::to_string(m_entry - 1) +
                             ": frame is " + text(size) + " but the first frame (entry " +
                             std::to_string(m_first_entry) + ") is " + text(m_first_size) +
                             "; all frames of a sequence must have one size");
  }
}

std::vector<JobPath> RawlogSource::inputs() const {
  std::vector<JobPath> out{{m_path, "the input rawlog"},
                           {groundTruthPathFor(m_path), "the input rawlog's ground truth"}};
  // The image folder MRPT falls back to may not exist (no external images): nothing to protect.
  if (std::filesystem::is_directory(m_images_dir))
    out.push_back({m_images_dir, "the input rawlog's image folder", true});
  return out;
}

std::string RawlogSource::describe() const {
  return "rawlog '" + m_path + "' (" + std::to_string(m_ground_truth.size()) +
         " ground-truth poses)";
}

}  // namespace hrgbd
