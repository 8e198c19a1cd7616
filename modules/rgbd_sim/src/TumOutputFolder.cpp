// checkTumOutputFolder(): rgbd-simulate --tum may not replace a dataset it did not write.
#include <filesystem>
#include <fstream>
#include <string>

#include "rgbd_core/Config.h"
#include "rgbd_sim/Simulator.h"

namespace hrgbd::sim {
namespace {

/** The list `path` starts with the header rgbd-simulate writes (its second line names it). */
bool simulatorList(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  for (int k = 0; k < 3 && std::getline(in, line); ++k)
    if (line.rfind("# file: rgbd-simulate ", 0) == 0) return true;
  return false;
}

}  // namespace

void checkTumOutputFolder(const std::string& folder) {
  namespace fs = std::filesystem;
  std::error_code ec;
  auto has = [&](const char* name) { return fs::exists(fs::path(folder) / name, ec); };
  auto refuse = [&](const char* name) {
    throw UsageError("--tum '" + folder + "' holds a TUM dataset rgbd-simulate did not write ('" +
                     (fs::path(folder) / name).string() +
                     "'); its lists, ground truth and camera would be replaced: give a new or "
                     "empty folder, or one rgbd-simulate wrote");
  };
  bool ours = false;
  for (const auto* list : {"rgb.txt", "depth.txt"}) {
    if (!has(list)) continue;
    if (!simulatorList((fs::path(folder) / list).string())) refuse(list);
    ours = true;
  }
  if (ours) return;
  for (const auto* other : {"groundtruth.txt", "calibration.txt"})
    if (has(other)) refuse(other);
}

}  // namespace hrgbd::sim
