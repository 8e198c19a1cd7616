#include "rgbd_core/Config.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/system/string_utils.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
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

namespace {

enum class Kind { Integer, Real, Bool, Text };

bool parseLong(const std::string& s, long& v) {
  if (s.empty()) return false;
  char* end = nullptr;
  errno = 0;
  v = std::strtol(s.c_str(), &end, 10);
  return errno == 0 && *end == '\0';
}

bool parseReal(const std::string& s, double& v) {
  if (s.empty()) return false;
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return *end == '\0';
}

// The kind of a key from the value MRPT writes for it: "%i" for integers, "%f" or "%e" for reals.
Kind kindOf(const std::string& written) {
  long l = 0;
  double d = 0;
  if (written == "true" || written == "false") return Kind::Bool;
  if (parseLong(written, l)) return Kind::Integer;
  if (parseReal(written, d)) return Kind::Real;
  return Kind::Text;
}

void checkSyntax(const std::string& section, const std::string& key, const std::string& value,
                 Kind kind) {
  auto fail = [&](const char* why) {
    throw ConfigError("[" + section + "] " + key + " = '" + value + "': " + why);
  };
  long l = 0;
  double d = 0;
  switch (kind) {
    case Kind::Integer:
      if (!parseLong(value, l) || l < INT_MIN || l > INT_MAX) fail("expects an integer");
      break;
    case Kind::Real:
      if (!parseReal(value, d)) fail("expects a number");
      if (!std::isfinite(d)) fail("expects a finite number");
      break;
    case Kind::Bool: {
      const auto v = mrpt::system::lowerCase(value);
      if (v != "true" && v != "false" && v != "1" && v != "0" && v != "yes" && v != "no")
        fail("expects true or false");
      break;
    }
    case Kind::Text:
      break;
  }
}

}  // namespace

void loadStrict(mrpt::config::CLoadableOptions& p, const mrpt::config::CConfigFileBase& cfg,
                const std::string& section) {
  mrpt::config::CConfigFileMemory written;
  p.saveToConfigFile(written, section);
  std::vector<std::string> sections;
  written.getAllSections(sections);
  for (const auto& s : sections) {
    std::vector<std::string> keys;
    written.getAllKeys(s, keys);
    for (const auto& k : keys) {
      if (!cfg.keyExists(s, k)) continue;
      const auto value = mrpt::system::trim(cfg.read_string(s, k, ""));
      checkSyntax(s, k, value, kindOf(mrpt::system::trim(written.read_string(s, k, ""))));
    }
  }
  p.loadFromConfigFile(cfg, section);
}

std::unique_ptr<mrpt::config::CConfigFileBase> loadIniFile(const std::string& path) {
  if (!std::ifstream(path).good()) throw ConfigError("cannot read config file '" + path + "'");
  try {
    return std::make_unique<mrpt::config::CConfigFile>(path);
  } catch (const std::exception& e) {  // MRPT's preprocessor: $env{}, $eval{}, @include, ...
    throw ConfigError("config file '" + path + "': " + errorText(e));
  }
}

}  // namespace hrgbd
