#pragma once
/** \file AppConfig.h
 * The configuration file as the apps see it: known sections, loading, the effective INI text. */
#include <mrpt/config/CConfigFileBase.h>

#include <memory>
#include <string>
#include <vector>

namespace hrgbd {

/** INI sections this project knows; any other section in a config file is an error. */
const std::vector<std::string>& knownConfigSections();

/** Throws ConfigError if `cfg` has a section not in knownConfigSections(). */
void rejectUnknownSections(const mrpt::config::CConfigFileBase& cfg);

/** Loads `file` ("" = built-in defaults) and rejects unknown sections (ConfigError). */
std::unique_ptr<mrpt::config::CConfigFileBase> loadChecked(const std::string& file);

/** The effective configuration (defaults + `config_file`, "" for defaults) as INI text. */
std::string effectiveConfig(const std::string& config_file);

}  // namespace hrgbd
