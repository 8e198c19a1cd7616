#include "rgbd_core/TextFile.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hrgbd {
namespace fs = std::filesystem;

std::string_view withoutBom(std::string_view text) {
  constexpr std::string_view bom = "\xEF\xBB\xBF";
  if (text.substr(0, bom.size()) == bom) text.remove_prefix(bom.size());
  return text;
}

std::string specialFileKind(const std::string& path) {
  std::error_code ec;
  const auto type = fs::status(path, ec).type();  // follows symbolic links (/dev/fd/63, /dev/stdin)
  switch (type) {
    case fs::file_type::directory:
      return "a folder";
    case fs::file_type::fifo:
      return "a FIFO (named pipe)";
    case fs::file_type::character:
      return "a character device";
    case fs::file_type::block:
      return "a block device";
    case fs::file_type::socket:
      return "a socket";
    default:
      return "";
  }
}

void requireRegularFile(const std::string& path, const std::string& what, const std::string& why) {
  const auto kind = specialFileKind(path);
  if (kind.empty()) return;
  throw std::runtime_error(what + " '" + path + "' is " + kind +
                           (kind == "a folder" ? ", not a file" : ", not a regular file") +
                           (why.empty() ? "" : "; " + why));
}

std::string readTextFile(const std::string& path, const std::string& what) {
  const auto kind = specialFileKind(path);
  // A folder opens without complaint and reads nothing; a device (/dev/zero) reads for ever.
  if (!kind.empty() && kind != "a FIFO (named pipe)") requireRegularFile(path, what);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + what + " '" + path + "'");
  std::string text;
  if (kind.empty()) {
    std::ostringstream whole;
    whole << in.rdbuf();
    text = whole.str();
  } else {  // read once, as it comes, up to the cap
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
      text.append(buffer, static_cast<std::size_t>(in.gcount()));
      if (text.size() > kMaxPipedText)
        throw std::runtime_error(what + " '" + path + "' is a pipe holding more than " +
                                 std::to_string(kMaxPipedText >> 20) +
                                 " MiB; a text input read from a pipe is read up to that size");
    }
  }
  if (in.bad()) throw std::runtime_error("cannot read " + what + " '" + path + "'");
  return std::string(withoutBom(text));
}

}  // namespace hrgbd
