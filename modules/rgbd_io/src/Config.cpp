#include "rgbd_io/Config.h"

#include <mrpt/config/CConfigFile.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

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
  return std::make_unique<mrpt::config::CConfigFile>(path);
}

}  // namespace hrgbd
