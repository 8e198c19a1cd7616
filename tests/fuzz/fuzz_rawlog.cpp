// Fuzz target: the rawlog reader, as playback uses it. The input is written to a file, opened
// with RawlogSource (plain or gzip) and up to 8 frames are read and prepared for registration.
// The reader either delivers frames or throws std::runtime_error naming the file and entry; a
// frame it delivers is prepared or refused with std::invalid_argument (the frame is flagged).
// Anything else, a crash or another exception, is a bug.
#include <stdexcept>

#include "FuzzUtil.h"
#include "rgbd_core/RgbdImage.h"
#include "rgbd_io/RawlogSource.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  static const auto path = hrgbd::fuzz::tempPath("input.rawlog");
  hrgbd::fuzz::writeFile(path, data, size);
  try {
    hrgbd::RawlogSource source(path);
    for (int i = 0; i < 8; ++i) {
      const auto obs = source.next();
      if (!obs) break;
      try {
        hrgbd::prepareRgbdImage(*obs);
      } catch (const std::invalid_argument&) {
      }
    }
  } catch (const std::runtime_error&) {
  }
  return 0;
}
