#include "rgbd_io/RawlogWriter.h"

#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/filesystem.h>

#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <vector>

#include "rgbd_core/ErrorText.h"
#include "rgbd_core/Interrupt.h"

namespace hrgbd {

std::string imagesFolderFor(const std::string& rawlog_path) {
  return std::filesystem::path(rawlog_path).replace_extension().string() + "_Images";
}

RawlogWriter::RawlogWriter(const std::string& path, ImageStorage images, int compression)
    : m_path(path), m_images(images) {
  // External images go beside the rawlog: a device (/dev/null) would get "/dev/null_Images".
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (images != ImageStorage::Inline && std::filesystem::exists(status) &&
      !std::filesystem::is_regular_file(status))
    throw std::runtime_error("cannot write rawlog '" + path +
                             "': with external images it must be a regular file (the images go "
                             "to '" +
                             imagesFolderFor(path) + "')");
  m_file = std::make_unique<GzOutputStream>(path, "rawlog", compression);
  m_archive = mrpt::serialization::archiveUniquePtrFrom(*m_file);
  if (images != ImageStorage::Inline) {
    // MRPT's convention, found by CRawlog::detectImagesDirectory(): "<stem>_Images/".
    m_images_dir = imagesFolderFor(path);
    m_made_folder = !std::filesystem::exists(m_images_dir, ec);
    std::filesystem::create_directories(m_images_dir, ec);
    if (ec || !std::filesystem::is_directory(m_images_dir))
      throw std::runtime_error("cannot create image folder '" + m_images_dir + "'");
  }
}

RawlogWriter::~RawlogWriter() {
  if (m_closed || m_images_dir.empty()) return;  // complete, or no external images
  std::error_code ec;
  for (const auto& f : m_image_files) std::filesystem::remove(f, ec);
  if (m_made_folder) std::filesystem::remove(m_images_dir, ec);  // only when empty
  if (interrupted() && !m_image_files.empty())
    noteNotWritten("the rawlog's images in '" + m_images_dir + "' (removed)");
}

void RawlogWriter::close() {
  if (!m_archive) throw std::logic_error("RawlogWriter: close() twice for '" + m_path + "'");
  m_archive.reset();
  m_file->close();  // the images stay only when this completes the rawlog
  m_closed = true;
}

void RawlogWriter::append(const mrpt::serialization::CSerializable& obj) {
  try {
    *m_archive << obj;
  } catch (const std::exception& e) {  // MRPT wraps the stream's error in its banner
    throw std::runtime_error(errorText(e));
  }
}

void RawlogWriter::write(const mrpt::serialization::CSerializable& obj) {
  if (!m_archive) throw std::logic_error("RawlogWriter: write after close() to '" + m_path + "'");
  const auto* scan = dynamic_cast<const mrpt::obs::CObservation3DRangeScan*>(&obj);
  if (m_images == ImageStorage::Inline || !scan || !scan->hasIntensityImage) {
    append(obj);
  } else {
    mrpt::obs::CObservation3DRangeScan copy = *scan;
    char name[64];
    std::snprintf(name, sizeof(name), "%s_%06zu.%s", scan->sensorLabel.c_str(), m_count,
                  m_images == ImageStorage::ExternalPng ? "png" : "jpg");
    // Encoded here and written as an OutputFile: cv::imwrite does not report a full disk.
    const bool png = m_images == ImageStorage::ExternalPng;
    std::vector<uchar> bytes;
    if (!cv::imencode(png ? ".png" : ".jpg", scan->intensityImage.asCvMatRef(), bytes,
                      {cv::IMWRITE_JPEG_QUALITY, 90}))
      throw std::runtime_error("cannot encode the image of frame " + std::to_string(m_count) +
                               " for '" + m_path + "'");
    const auto file = m_images_dir + "/" + name;
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) m_image_files.push_back(file);  // an older run's stay
    writeOutputFile(file, "image", bytes.data(), bytes.size());
    copy.intensityImage.setExternalStorage(name);
    append(copy);
  }
  ++m_count;
}

}  // namespace hrgbd
