// RawlogSource::frameCount(): the frames of a rawlog, counted before the run for its progress.
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>

#include "ReadGuards.h"
#include "rgbd_io/RawlogSource.h"

namespace hrgbd {

std::size_t RawlogSource::frameCount(std::size_t at_most) const {
  using mrpt::obs::CObservation3DRangeScan;
  mrpt::io::CFileGZInputStream file;
  if (!file.open(m_path)) return 0;
  auto archive = mrpt::serialization::archiveFrom(file);
  std::size_t frames = 0;
  try {
    while (at_most == 0 || frames < at_most) {
      const ReadingRawlogEntry reading;
      const auto obj = archive.ReadObject();
      if (std::dynamic_pointer_cast<CObservation3DRangeScan>(obj)) {
        ++frames;
      } else if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj)) {
        frames += std::count_if(sf->begin(), sf->end(), [](const auto& o) {
          return std::dynamic_pointer_cast<CObservation3DRangeScan>(o) != nullptr;
        });
      }
    }
    return std::min(frames, at_most);  // a SensoryFrame may hold more than one
  } catch (const mrpt::serialization::CExceptionEOF&) {
    return frames;
  } catch (const std::exception&) {
    return 0;  // corrupt: next() says where
  }
}

}  // namespace hrgbd
