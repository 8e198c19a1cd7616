#pragma once
/** \file RawlogWriter.h
 * Writes observations to a gzip rawlog (observations-only format) that RawLogViewer and
 * rawlog-edit open. */
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/typemeta/TEnumType.h>

#include <memory>
#include <string>

namespace mrpt::serialization {
class CArchive;
class CSerializable;
}  // namespace mrpt::serialization

namespace hrgbd {

/** How colour images are stored. */
enum class ImageStorage {
  Inline,        //!< inside the rawlog (self-contained, larger)
  ExternalPng,   //!< lossless PNG files in "<stem>_Images/", as MRPT's grabbers do
  ExternalJpeg,  //!< JPEG (quality 90) in "<stem>_Images/", for small bundled sequences
};

}  // namespace hrgbd

// The names of ImageStorage in INI files and on the command line (`--images`).
MRPT_ENUM_TYPE_BEGIN(hrgbd::ImageStorage)
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::ImageStorage::Inline, "inline");
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::ImageStorage::ExternalPng, "png");
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::ImageStorage::ExternalJpeg, "jpg");
MRPT_ENUM_TYPE_END()

namespace hrgbd {

class RawlogWriter {
 public:
  /** Opens `path` for writing (gzip level `compression`, 1..9); throws if it cannot. */
  explicit RawlogWriter(const std::string& path, ImageStorage images = ImageStorage::Inline,
                        int compression = 6);
  ~RawlogWriter();
  /** Appends one object (observation, SensoryFrame, ...; gzip buffers it until close). 3D range
   * scans with external storage get their colour image written to a file first; the caller's object
   * is not modified. */
  void write(const mrpt::serialization::CSerializable& obj);
  std::size_t written() const { return m_count; }

 private:
  std::string m_path, m_images_dir;
  ImageStorage m_images;
  mrpt::io::CFileGZOutputStream m_file;
  std::unique_ptr<mrpt::serialization::CArchive> m_archive;
  std::size_t m_count = 0;
};

}  // namespace hrgbd
