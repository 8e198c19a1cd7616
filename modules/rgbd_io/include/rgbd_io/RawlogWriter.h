#pragma once
/** \file RawlogWriter.h
 * Writes observations to a gzip rawlog (observations-only format) that RawLogViewer and
 * rawlog-edit open, in full or not at all. */
#include <mrpt/obs/CObservation.h>
#include <mrpt/typemeta/TEnumType.h>

#include <memory>
#include <string>
#include <vector>

#include "rgbd_core/GzOutput.h"

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

/** The folder of a rawlog's external images, MRPT's convention: "<dir>/<stem>_Images". */
std::string imagesFolderFor(const std::string& rawlog_path);

class RawlogWriter {
 public:
  /** Starts `path` (gzip level `compression`, 1..9) as an OutputFile: the rawlog appears under
   * its name only when close() succeeds. External images go straight into imagesFolder(),
   * created here; with them, `path` must be a regular file (not a device such as /dev/null).
   * Throws naming the file or folder if it cannot. */
  explicit RawlogWriter(const std::string& path, ImageStorage images = ImageStorage::Inline,
                        int compression = 6);
  /** Without close() (an error, Ctrl-C): the rawlog is discarded, and so are the images written
   * for it, with the image folder when this writer created it: no half-written `_Images/`. */
  ~RawlogWriter();
  /** Appends one object (observation, SensoryFrame, ...). 3D range scans with external storage
   * get their colour image written to a file first; the caller's object is not modified. Throws
   * naming the file when a write fails. */
  void write(const mrpt::serialization::CSerializable& obj);
  /** Completes the gzip stream, checks it and moves the rawlog into place; throws naming the file
   * on failure (e.g. a full disk). */
  void close();
  std::size_t written() const { return m_count; }
  /** Where external images go ("" for inline storage). */
  const std::string& imagesFolder() const { return m_images_dir; }

 private:
  void append(const mrpt::serialization::CSerializable& obj);

  std::string m_path, m_images_dir;
  ImageStorage m_images;
  std::unique_ptr<GzOutputStream> m_file;
  std::unique_ptr<mrpt::serialization::CArchive> m_archive;
  std::size_t m_count = 0;
  bool m_closed = false;                   //!< close() completed the rawlog
  bool m_made_folder = false;              //!< the image folder did not exist before
  std::vector<std::string> m_image_files;  //!< written, removed again without close()
};

}  // namespace hrgbd
