#include "rgbd_io/TumLists.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "rgbd_core/TextFile.h"
#include "rgbd_core/TimeAssociation.h"
#include "rgbd_core/Timestamp.h"

namespace hrgbd {

std::vector<TumListEntry> parseTumListText(const std::string& text, const std::string& name) {
  std::vector<TumListEntry> out;
  std::istringstream in(std::string(withoutBom(text)));
  std::string line;
  for (int line_no = 1; std::getline(in, line); ++line_no) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream ss(line);
    TumListEntry e;
    e.line = line_no;
    const auto where = "'" + name + "' line " + std::to_string(line_no);
    std::string stamp;
    if (!(ss >> stamp >> e.file))
      throw std::runtime_error(where + ": expected 'timestamp filename'");
    try {
      e.stamp = parseFrameTime(stamp);
    } catch (const std::invalid_argument& bad) {
      throw std::runtime_error(where + ": " + bad.what());
    }
    e.t = frameSeconds(e.stamp);
    if (!out.empty() && !(e.stamp > out.back().stamp))
      throw std::runtime_error(where + ": time stamp " + stamp +
                               " is not after the previous one (" +
                               formatFrameTime(out.back().stamp) +
                               "); TUM lists must be in strictly increasing time order");
    out.push_back(e);
  }
  return out;
}

TumCalibration parseTumCalibrationText(const std::string& text, const std::string& name) {
  std::istringstream in(std::string(withoutBom(text)));
  std::string line;
  int found_at = 0;
  TumCalibration c;
  for (int line_no = 1; std::getline(in, line); ++line_no) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    const auto where = "'" + name + "' line " + std::to_string(line_no);
    if (found_at > 0)
      throw std::runtime_error(where + ": a second line of values (line " +
                               std::to_string(found_at) +
                               " gave them); expected one 'fx fy cx cy'");
    std::istringstream ss(line);
    std::string extra;
    // (>> fails on nan, inf and values out of the double's range)
    if (!(ss >> c.fx >> c.fy >> c.cx >> c.cy) || ss >> extra)
      throw std::runtime_error(where + ": expected 'fx fy cx cy', four finite numbers in pixels");
    if (!(c.fx > 0 && c.fy > 0))
      throw std::runtime_error(where + ": the focal lengths fx, fy must be positive");
    found_at = line_no;
  }
  if (found_at == 0) throw std::runtime_error("'" + name + "' holds no 'fx fy cx cy' line");
  return c;
}

std::vector<TumListEntry> parseTumList(const std::string& path) {
  return parseTumListText(readTextFile(path, "TUM list"), path);
}

std::vector<TumPair> associateTumLists(const std::vector<TumListEntry>& rgb,
                                       const std::vector<TumListEntry>& depth, double max_dt) {
  auto times = [](const std::vector<TumListEntry>& v) {
    std::vector<double> t;
    for (const auto& e : v) t.push_back(e.t);
    return t;
  };
  std::vector<TumPair> pairs;
  for (const auto& [i, j] : associateByTime(times(rgb), times(depth), max_dt))
    pairs.push_back({rgb[i], depth[j]});
  return pairs;
}

}  // namespace hrgbd
