#include "rgbd_io/openFrameSource.h"

#include <mrpt/system/filesystem.h>

#include "rgbd_core/Config.h"
#include "rgbd_io/OniFileSource.h"
#include "rgbd_io/OpenNI2Source.h"
#include "rgbd_io/RawlogSource.h"
#include "rgbd_io/TumSource.h"

namespace hrgbd {

std::unique_ptr<FrameSource> openFrameSource(const std::string& input,
                                             const mrpt::config::CConfigFileBase& cfg) {
  if (input == "openni2") return std::make_unique<OpenNI2Source>(cfg, "OpenNI2");
  if (isOniFile(input)) return std::make_unique<OniFileSource>(input);
  if (mrpt::system::directoryExists(input)) {
    TumSourceParams p;
    p.loadFromConfigFile(cfg, "TumSource");
    return std::make_unique<TumSource>(input, p);
  }
  return std::make_unique<RawlogSource>(input);
}

}  // namespace hrgbd
