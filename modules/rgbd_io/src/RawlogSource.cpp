#include "rgbd_io/RawlogSource.h"

#include <mrpt/img/CImage.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/system/filesystem.h>

#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "ReadGuards.h"
#include "rgbd_core/ErrorText.h"
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

}  // namespace

std::string groundTruthPathFor(const std::string& rawlog_path) {
  return std::filesystem::path(rawlog_path).replace_extension().string() + "_groundtruth.txt";
}

RawlogSource::RawlogSource(const std::string& path) : m_path(path) {
  installReadGuards();
  if (!mrpt::system::fileExists(path))
    throw std::runtime_error("rawlog '" + path + "' does not exist");
  if (!m_file.open(path)) throw std::runtime_error("cannot open rawlog '" + path + "'");
  m_archive =
      std::make_unique<mrpt::serialization::CArchiveStreamBase<mrpt::io::CFileGZInputStream>>(
          m_file);
  // "<stem>_Images" first: MRPT 2.5's detectImagesDirectory() misses it for absolute paths.
  const auto own = std::filesystem::path(path).replace_extension().string() + "_Images";
  m_images_dir =
      std::filesystem::is_directory(own) ? own : mrpt::obs::CRawlog::detectImagesDirectory(path);
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
      // A clean end leaves no byte of a partial object behind.
      if (m_file.getPosition() == start) return nullptr;
      throw std::runtime_error("rawlog '" + m_path + "' is truncated inside entry " +
                               std::to_string(m_entry) + " (at byte " + std::to_string(start) +
                               " of the uncompressed stream)");
    } catch (const std::exception& e) {
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
  try {
    checkFrameTime(obs->timestamp);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error("rawlog '" + m_path + "' entry " + std::to_string(m_entry - 1) + ": " +
                             e.what());
  }
  if (obs->hasIntensityImage && obs->intensityImage.isExternallyStored()) {
    mrpt::img::CImage::setImagesPathBase(m_images_dir);
    const auto file = obs->intensityImage.getExternalStorageFileAbsolutePath();
    if (!mrpt::system::fileExists(file))
      throw std::runtime_error("rawlog '" + m_path + "' entry " + std::to_string(m_entry - 1) +
                               ": external image '" + file + "' is missing");
  }
  try {
    obs->load();
  } catch (const std::exception& e) {
    throw std::runtime_error("rawlog '" + m_path + "' entry " + std::to_string(m_entry - 1) +
                             ": cannot load external data: " + errorText(e));
  }
  ++m_stats.frames;
  return obs;
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
