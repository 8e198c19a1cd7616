#pragma once
/** \file AppConfig.h
 * The configuration file as the apps see it: loading with the section check of the configuration
 * layer (knownConfigSections() in rgbd_core/Config.h), the effective INI text. */
#include <mrpt/config/CConfigFileBase.h>

#include <memory>
#include <string>
#include <vector>

#include "rgbd_core/Config.h"

namespace hrgbd {

/** Loads `file` ("" = built-in defaults) and rejects unknown sections (ConfigError). */
std::unique_ptr<mrpt::config::CConfigFileBase> loadChecked(const std::string& file);

/** The effective configuration (defaults + `config_file`, "" for defaults) as INI text. */
std::string effectiveConfig(const std::string& config_file);

}  // namespace hrgbd
