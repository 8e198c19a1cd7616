#include "rgbd_core/TextFile.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hrgbd {

std::string_view withoutBom(std::string_view text) {
  constexpr std::string_view bom = "\xEF\xBB\xBF";
  if (text.substr(0, bom.size()) == bom) text.remove_prefix(bom.size());
  return text;
}

std::string readTextFile(const std::string& path, const std::string& what) {
  std::error_code ec;
  // An ifstream opens a folder without complaint and then reads nothing from it.
  if (std::filesystem::is_directory(path, ec))
    throw std::runtime_error(what + " '" + path + "' is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + what + " '" + path + "'");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw std::runtime_error("cannot read " + what + " '" + path + "'");
  return std::string(withoutBom(text.str()));
}

}  // namespace hrgbd
