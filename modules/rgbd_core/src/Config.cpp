#include "rgbd_core/Config.h"

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/config/config_parser.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <sstream>

#include "rgbd_core/ErrorText.h"
#include "rgbd_core/TextFile.h"

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

std::string iniFolder(const std::string& config) {
  const auto folder = std::filesystem::path(config).parent_path();
  return folder.empty() ? "." : folder.string();
}

void rejectMalformedLines(const std::string& text, const std::string& name) {
  // MRPT merges a repeated section and keeps one of two values of a key without a word; these
  // are nearly always editing mistakes (a pasted block), so they are refused. So are the lines
  // it skips without a word: a key before any section, and a line that is neither a
  // [section] nor key = value (a missing '=', an unclosed '[').
  std::map<std::string, int> sections;                      // section -> line
  std::map<std::pair<std::string, std::string>, int> keys;  // (section, key) -> line
  std::string section;
  std::istringstream in(text);
  std::string line;
  for (int line_no = 1, next_no = 1; std::getline(in, line); line_no = ++next_no) {
    // MRPT's preprocessor joins a line ending in '\' with the next one.
    std::string more;
    for (auto end = line.find_last_not_of(" \t\r");
         end != std::string::npos && line[end] == '\\' && std::getline(in, more);
         end = line.find_last_not_of(" \t\r"), ++next_no)
      line = line.substr(0, end) + more;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    line = line.substr(first, line.find_last_not_of(" \t\r") + 1 - first);
    if (line[0] == ';' || line[0] == '#' || line.rfind("//", 0) == 0) continue;
    const auto where = "config file '" + name + "' line " + std::to_string(line_no) + ": ";
    if (line[0] == '@') {
      // MRPT's preprocessor knows "@define NAME VALUE" only; it leaves any other '@' line (an
      // "@include other.ini") to the INI parser, which skips it without a word.
      if (line.rfind("@define", 0) == 0 && line.find_first_of(" \t") == 7) continue;
      const auto directive = line.substr(0, line.find_first_of(" \t"));
      throw ConfigError(where + "'" + line + "': MRPT's INI files have no " + directive +
                        " (only @define), so it would be ignored; copy the keys it should " +
                        "bring into this file");
    }
    if (line.find("${") != std::string::npos) continue;  // an @define'd variable: seen expanded
    if (line[0] == '[' && line.find(']') == std::string::npos)
      throw ConfigError(where + "'" + line + "' opens a section without closing it with ']'");
    if (line[0] == '[') {
      section = line.substr(1, line.find(']') - 1);
      const auto [it, fresh] = sections.emplace(section, line_no);
      if (!fresh)
        throw ConfigError(where + "section [" + section + "] appears again (first on line " +
                          std::to_string(it->second) + "); give each section once");
      continue;
    }
    const auto eq = line.find('=');
    if (eq == std::string::npos)
      throw ConfigError(where + "'" + line + "' is neither a [section] nor key = value");
    auto key = line.substr(0, eq);
    key.erase(key.find_last_not_of(" \t") + 1);
    if (key.empty()) throw ConfigError(where + "'" + line + "' gives a value without a key");
    if (section.empty())
      throw ConfigError(where + "'" + key + "' comes before any [section]; put it in one");
    const auto [it, fresh] = keys.emplace(std::make_pair(section, key), line_no);
    if (!fresh)
      throw ConfigError(where + "[" + section + "] " + key + " is given again (first on line " +
                        std::to_string(it->second) + "); give each key once per section");
  }
}

std::unique_ptr<mrpt::config::CConfigFileBase> loadIniFile(const std::string& path) {
  std::string text;
  try {
    text = readTextFile(path, "config file");  // read once: a FIFO or `-c <(...)` too
  } catch (const std::runtime_error& e) {
    throw ConfigError(e.what());
  }
  rejectMalformedLines(text, path);
  try {
    // What CConfigFile(path) does, on the text already read (it opened the file again, and
    // sized its buffer by seeking to the end, which a pipe cannot: "basic_string::_M_create").
    return std::make_unique<mrpt::config::CConfigFileMemory>(mrpt::config::config_parser(text));
  } catch (const std::exception& e) {  // MRPT's preprocessor: $env{}, $eval{}, ...
    throw ConfigError("config file '" + path + "': " + errorText(e));
  }
}

const std::vector<std::string>& knownConfigSections() {
  static const std::vector<std::string> s{"Playback",  "Odometry", "ORB",       "Geometric", "MSSE",
                                          "Dense",     "Slam",     "RANSAC",    "ICP",       "Map",
                                          "TumSource", "OpenNI2",  "Simulator", "Benchmark"};
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
