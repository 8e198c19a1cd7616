#include "rgbd_core/Config.h"

#include <mrpt/config/CConfigFile.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "rgbd_core/ErrorText.h"

namespace hrgbd {

void rejectUnknownKeys(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                       const std::vector<std::string>& known) {
  std::vector<std::string> keys;
  cfg.getAllKeys(section, keys);
  for (const auto& k : keys) {
    if (std::find(known.begin(), known.end(), k) != known.end()) continue;
    std::ostringstream msg;
    msg << "[" << section << "] unknown key '" << k << "'. Known keys:";
    for (const auto& n : known) msg << " " << n;
    throw ConfigError(msg.str());
  }
}

void requireValid(bool ok, const std::string& section, const std::string& key, double value,
                  const std::string& why) {
  if (ok) return;
  std::ostringstream msg;
  msg << "[" << section << "] " << key << " = " << value << ": " << why;
  throw ConfigError(msg.str());
}

std::string resolvePath(const std::string& base, const std::string& path) {
  if (path.empty() || std::filesystem::path(path).is_absolute()) return path;
  return (std::filesystem::path(base) / path).lexically_normal().string();
}

std::unique_ptr<mrpt::config::CConfigFileBase> loadIniFile(const std::string& path) {
  if (!std::ifstream(path).good()) throw ConfigError("cannot read config file '" + path + "'");
  try {
    return std::make_unique<mrpt::config::CConfigFile>(path);
  } catch (const std::exception& e) {  // MRPT's preprocessor: $env{}, $eval{}, @include, ...
    throw ConfigError("config file '" + path + "': " + errorText(e));
  }
}

const std::vector<std::string>& knownConfigSections() {
  static const std::vector<std::string> s{
      "Playback", "Odometry", "ORB",       "Geometric", "MSSE",      "Dense",    "Slam", "RANSAC",
      "ICP",      "Map",      "TumSource", "OpenNI2",   "Simulator", "Benchmark"};
  return s;
}

void rejectUnknownSections(const mrpt::config::CConfigFileBase& cfg) {
  std::vector<std::string> sections;
  cfg.getAllSections(sections);
  const auto& known = knownConfigSections();
  for (const auto& s : sections)
    if (!s.empty() && std::find(known.begin(), known.end(), s) == known.end()) {
      std::string list;
      for (const auto& k : known) list += " [" + k + "]";
      throw ConfigError("unknown INI section [" + s + "]. Known sections:" + list);
    }
}

}  // namespace hrgbd
