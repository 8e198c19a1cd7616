#include "rgbd_core/ErrorText.h"

#include <mrpt/system/string_utils.h>

#include <sstream>

namespace hrgbd {

std::string errorText(const std::exception& e) {
  std::istringstream in(e.what());
  std::string line, out;
  while (std::getline(in, line)) {
    line = mrpt::system::trim(line);
    if (line.rfind("Call stack backtrace", 0) == 0) break;
    if (line.empty() || line.rfind("====", 0) == 0) continue;
    // "Location: ./libs/img/src/CImage.cpp:1667: [void mrpt::img::...]" says nothing to a user
    if (line.rfind("Location:", 0) == 0) continue;
    if (line.rfind("Message:", 0) == 0) line = mrpt::system::trim(line.substr(8));
    out += (out.empty() ? "" : "; ") + line;
  }
  return out.empty() ? e.what() : out;
}

}  // namespace hrgbd
