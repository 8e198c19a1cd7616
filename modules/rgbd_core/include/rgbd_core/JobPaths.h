#pragma once
/** \file JobPaths.h
 * The files and folders a job reads and writes, and the check that no output would overwrite an
 * input or another output. Every app runs it before it writes anything. */
#include <string>
#include <vector>

namespace hrgbd {

/** A file or folder a job reads or writes, named as the user knows it. */
struct JobPath {
  std::string path;  //!< "" = not used (skipped by the check)
  /** The option or INI key that gave it ("--trajectory", "[Playback] csv"), or what it is
   * ("the TUM folder's rgb.txt"). */
  std::string name;
  bool folder = false;  //!< a folder: everything inside it belongs to it
  /** For outputs: the command line named it (a conflict is then a UsageError, exit 2), else a
   * configuration file did (ConfigError). */
  bool from_command_line = false;
};

/** Throws, before anything is written, if an output is an input file, lies inside an input
 * folder, or is a folder holding an input; or if two outputs are the same file (except an
 * existing device or FIFO such as /dev/null, which any number of outputs may share). Paths are
 * compared resolved: relative to the working directory, "..", symbolic links (weakly_canonical)
 * and hard links (equivalent). The message names both paths and the option or key of each. */
void checkJobPaths(const std::vector<JobPath>& inputs, const std::vector<JobPath>& outputs);

/** Whether one of `paths` is the file the standard output writes to (`/dev/stdout`, or the file
 * stdout is redirected to): an app then writes its messages to stderr, which would otherwise be
 * mixed into that output. */
bool writesStandardOutput(const std::vector<std::string>& paths);

}  // namespace hrgbd
