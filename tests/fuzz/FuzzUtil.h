#pragma once
/** \file FuzzUtil.h
 * Helpers shared by the fuzz targets: the readers under test take paths, so each input is written
 * to a per-process temporary file first. */
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace hrgbd::fuzz {

/** "<tmp>/hrgbd_fuzz_<pid>_<name>", the same path on every call of one process; removed when
 * the process exits normally (a crash leaves it in the temporary folder). */
inline std::string tempPath(const std::string& name) {
  struct Removed {
    std::vector<std::string> paths;
    ~Removed() {
      std::error_code ignored;
      for (const auto& p : paths) std::filesystem::remove(p, ignored);
    }
  };
  static Removed removed;
  const auto p = (std::filesystem::temp_directory_path() /
                  ("hrgbd_fuzz_" + std::to_string(::getpid()) + "_" + name))
                     .string();
  if (std::find(removed.paths.begin(), removed.paths.end(), p) == removed.paths.end())
    removed.paths.push_back(p);
  return p;
}

/** Writes the input to `path`, replacing what was there. */
inline void writeFile(const std::string& path, const uint8_t* data, std::size_t size) {
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

}  // namespace hrgbd::fuzz
