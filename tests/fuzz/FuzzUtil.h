#pragma once
/** \file FuzzUtil.h
 * Helpers shared by the fuzz targets: the readers under test take paths, so each input is written
 * to a per-process temporary file first. */
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace hrgbd::fuzz {

/** "<tmp>/hrgbd_fuzz_<pid>_<name>", the same path on every call of one process. */
inline std::string tempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("hrgbd_fuzz_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

/** Writes the input to `path`, replacing what was there. */
inline void writeFile(const std::string& path, const uint8_t* data, std::size_t size) {
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

}  // namespace hrgbd::fuzz
