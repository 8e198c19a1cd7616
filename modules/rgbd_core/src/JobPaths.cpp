#include "rgbd_core/JobPaths.h"

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>

#include "rgbd_core/Config.h"

namespace hrgbd {
namespace fs = std::filesystem;

namespace {

fs::path resolved(const std::string& p) {
  std::error_code ec;
  auto r = fs::weakly_canonical(fs::absolute(p), ec);
  return ec ? fs::absolute(p).lexically_normal() : r;
}

/** The same file: one resolved path, or two names of one existing file (hard links). */
bool sameFile(const fs::path& a, const fs::path& b) {
  if (a == b) return true;
  std::error_code ec;
  return fs::equivalent(a, b, ec) && !ec;
}

/** `inner` is `folder` or lies somewhere inside it (both resolved). */
bool inside(const fs::path& inner, fs::path folder) {
  if (folder.filename().empty()) folder = folder.parent_path();  // "x_Images/"
  const auto rel = inner.lexically_relative(folder);
  return !rel.empty() && *rel.begin() != "..";
}

/** A device, FIFO or socket that exists: written in place, any number of outputs may share it. */
bool special(const fs::path& p) {
  std::error_code ec;
  const auto s = fs::status(p, ec);
  return fs::exists(s) && !fs::is_regular_file(s) && !fs::is_directory(s);
}

std::string quoted(const JobPath& p) { return p.name + " '" + p.path + "'"; }

[[noreturn]] void conflict(const JobPath& output, const std::string& what) {
  if (output.from_command_line) throw UsageError(what);
  throw ConfigError(what);
}

}  // namespace

void checkJobPaths(const std::vector<JobPath>& inputs, const std::vector<JobPath>& outputs) {
  auto resolveAll = [](const std::vector<JobPath>& paths) {
    std::vector<fs::path> out;
    for (const auto& p : paths) out.push_back(p.path.empty() ? fs::path() : resolved(p.path));
    return out;
  };
  const auto in_paths = resolveAll(inputs), out_paths = resolveAll(outputs);
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    const auto& out = outputs[k];
    const auto& o = out_paths[k];
    if (out.path.empty()) continue;
    for (std::size_t n = 0; n < inputs.size(); ++n) {
      const auto& in = inputs[n];
      const auto& i = in_paths[n];
      if (in.path.empty()) continue;
      if (sameFile(o, i)) conflict(out, quoted(out) + " would overwrite " + quoted(in));
      if (in.folder && inside(o, i)) conflict(out, quoted(out) + " lies inside " + quoted(in));
      if (out.folder && inside(i, o))
        conflict(out, quoted(out) + " would write over " + quoted(in) + ", which lies inside it");
    }
    for (std::size_t j = 0; j < k; ++j) {
      const auto& other = outputs[j];
      if (other.path.empty() || out.folder || other.folder) continue;
      if (sameFile(o, out_paths[j]) && !special(o))
        conflict(out.from_command_line ? out : other,
                 quoted(other) + " and " + quoted(out) + " are the same file");
    }
  }
}

bool writesStandardOutput(const std::vector<std::string>& paths) {
  struct stat out {};
  if (::fstat(STDOUT_FILENO, &out) != 0) return false;
  for (const auto& p : paths) {
    struct stat s {};
    if (!p.empty() && ::stat(p.c_str(), &s) == 0 && s.st_dev == out.st_dev &&
        s.st_ino == out.st_ino)
      return true;
  }
  return false;
}

}  // namespace hrgbd
