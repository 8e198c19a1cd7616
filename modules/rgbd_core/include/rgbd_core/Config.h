#pragma once
/** \file Config.h
 * The configuration file: errors, the registry of INI sections, loading, and helpers of the
 * params structs (Params.h). MRPT's CLoadableOptions ignore unknown keys; ours reject them. */
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/typemeta/TEnumType.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace hrgbd {

/** Thrown for any configuration problem; the message names the section and key. */
struct ConfigError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

/** Thrown by an app's work for a command line that parses but is incomplete or inconsistent
 * (e.g. no output given, an output naming an input); CommandLine::run() (rgbd_cli) reports it
 * like a parse error (exit 2). Throw it before any output is written. */
struct UsageError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

/** Throws ConfigError if `section` holds a key not in `known`. */
void rejectUnknownKeys(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                       const std::vector<std::string>& known);

/** Throws ConfigError "[section] key = value: <why>" unless `ok`. */
void requireValid(bool ok, const std::string& section, const std::string& key, double value,
                  const std::string& why);

/** `path` relative to `base` (the INI file's folder) unless it is empty or absolute. */
std::string resolvePath(const std::string& base, const std::string& path);

/** The folder of INI file `config`, against which its relative paths are resolved ("." for no
 * file). */
std::string iniFolder(const std::string& config);

/** Every name of an enum declared with MRPT_ENUM_TYPE_BEGIN / MRPT_FILL_ENUM_CUSTOM_NAME, in
 * declaration order: the allowed values for INI files and command lines. */
template <class E>
std::vector<std::string> enumNameList() {
  std::vector<std::string> out;
  for (const auto& kv : mrpt::typemeta::TEnumType<E>::getBimap().m_k2v) out.push_back(kv.second);
  return out;
}

/** enumNameList() joined by `sep`. */
template <class E>
std::string enumNames(const std::string& sep = "|") {
  std::string out;
  for (const auto& name : enumNameList<E>()) out += (out.empty() ? "" : sep) + name;
  return out;
}

/** The enum value named `name`; ConfigError "[section] key = 'name': must be a|b|c" otherwise
 * (numbers are not accepted, unlike MRPT's read_enum). */
template <class E>
E parseEnum(const std::string& name, const std::string& section, const std::string& key) {
  E v{};
  if (!mrpt::typemeta::TEnumType<E>::getBimap().inverse(name, v))
    throw ConfigError("[" + section + "] " + key + " = '" + name + "': must be " + enumNames<E>());
  return v;
}

/** Throws ConfigError naming the file (`name`), line and section or key when INI `text` gives a
 * section twice or a key twice in one section (MRPT would merge or pick one silently), or has a
 * line MRPT would skip silently: a key before any section, an unclosed '[', a line that is
 * neither a [section] nor key = value, a preprocessor line other than "@define" ("@include",
 * which MRPT does not support). */
void rejectMalformedLines(const std::string& text, const std::string& name);

/** Loads an INI file, read once (readTextFile(): a pipe or FIFO too, a device refused), throwing
 * ConfigError if it is missing, a folder or unreadable, or if it repeats a section or key or has a
 * malformed line (rejectMalformedLines()). MRPT's preprocessor (@define, ${}, $env{}, $eval{})
 * runs on it as in CConfigFile. */
std::unique_ptr<mrpt::config::CConfigFileBase> loadIniFile(const std::string& path);

/** Every INI section any app of this project reads, so that one file can hold them all:
 * [Playback], [Odometry] with its stage sections [ORB] [Geometric] [MSSE] [RANSAC] [ICP], [Map],
 * [TumSource], [OpenNI2] (MRPT's COpenNI2Sensor keys), [Simulator] and [Benchmark]. */
const std::vector<std::string>& knownConfigSections();

/** Throws ConfigError naming the first section of `cfg` not in knownConfigSections(). */
void rejectUnknownSections(const mrpt::config::CConfigFileBase& cfg);

}  // namespace hrgbd
