#pragma once
/** \file openFrameSource.h
 * Picks the FrameSource for an input name. */
#include <mrpt/config/CConfigFileBase.h>

#include <memory>
#include <string>

#include "rgbd_io/FrameSource.h"

namespace hrgbd {

/** "openni2" -> live sensor (INI section [OpenNI2]); "*.oni" -> OpenNI recording played
 * through OpenNI2's file driver (OniFileSource.h); a folder -> TUM dataset (INI section
 * [TumSource]); anything else -> rawlog file. Throws with a clear message if it cannot open. */
std::unique_ptr<FrameSource> openFrameSource(const std::string& input,
                                             const mrpt::config::CConfigFileBase& cfg);

}  // namespace hrgbd
