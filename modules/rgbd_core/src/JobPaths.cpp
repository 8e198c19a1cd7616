#include "rgbd_core/JobPaths.h"

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

/** `inner` is `folder` or lies somewhere inside it. */
bool inside(const fs::path& inner, const fs::path& folder) {
  auto i = inner.begin();
  for (auto f = folder.begin(); f != folder.end(); ++f, ++i)
    if (f->empty() && std::next(f) == folder.end())
      break;  // trailing separator
    else if (i == inner.end() || *i != *f)
      return false;
  return true;
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
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    const auto& out = outputs[k];
    if (out.path.empty()) continue;
    const auto o = resolved(out.path);
    for (const auto& in : inputs) {
      if (in.path.empty()) continue;
      const auto i = resolved(in.path);
      if (sameFile(o, i)) conflict(out, quoted(out) + " would overwrite " + quoted(in));
      if (in.folder && inside(o, i)) conflict(out, quoted(out) + " lies inside " + quoted(in));
      if (out.folder && inside(i, o))
        conflict(out, quoted(out) + " would write over " + quoted(in) + ", which lies inside it");
    }
    for (std::size_t j = 0; j < k; ++j) {
      const auto& other = outputs[j];
      if (other.path.empty() || out.folder || other.folder) continue;
      const auto p = resolved(other.path);
      if (sameFile(o, p) && !special(o))
        conflict(out.from_command_line ? out : other,
                 quoted(other) + " and " + quoted(out) + " are the same file");
    }
  }
}

}  // namespace hrgbd
