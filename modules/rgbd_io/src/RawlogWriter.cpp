#include "rgbd_io/RawlogWriter.h"

#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/filesystem.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace hrgbd {

RawlogWriter::RawlogWriter(const std::string& path, ImageStorage images, int compression)
    : m_path(path), m_images(images) {
  if (!m_file.open(path, compression))
    throw std::runtime_error("cannot write rawlog '" + path + "'");
  m_archive =
      std::make_unique<mrpt::serialization::CArchiveStreamBase<mrpt::io::CFileGZOutputStream>>(
          m_file);
  if (images != ImageStorage::Inline) {
    // MRPT's convention, found by CRawlog::detectImagesDirectory(): "<stem>_Images/".
    m_images_dir = std::filesystem::path(path).replace_extension().string() + "_Images";
    std::error_code ec;
    std::filesystem::create_directories(m_images_dir, ec);
    if (ec || !std::filesystem::is_directory(m_images_dir))
      throw std::runtime_error("cannot create image folder '" + m_images_dir + "'");
  }
}

RawlogWriter::~RawlogWriter() = default;

void RawlogWriter::write(const mrpt::serialization::CSerializable& obj) {
  const auto* scan = dynamic_cast<const mrpt::obs::CObservation3DRangeScan*>(&obj);
  if (m_images == ImageStorage::Inline || !scan || !scan->hasIntensityImage) {
    *m_archive << obj;
  } else {
    mrpt::obs::CObservation3DRangeScan copy = *scan;
    char name[64];
    std::snprintf(name, sizeof(name), "%s_%06zu.%s", scan->sensorLabel.c_str(), m_count,
                  m_images == ImageStorage::ExternalPng ? "png" : "jpg");
    const std::string file = m_images_dir + "/" + name;
    if (!scan->intensityImage.saveToFile(file, 90))
      throw std::runtime_error("cannot write image '" + file + "'");
    copy.intensityImage.setExternalStorage(name);
    *m_archive << copy;
  }
  ++m_count;
}

}  // namespace hrgbd
