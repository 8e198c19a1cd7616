#include "ImageFiles.h"

#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace hrgbd {

void refuseHugePng(const std::string& path) {
  unsigned char h[24] = {};
  std::ifstream in(path, std::ios::binary);
  if (!in.read(reinterpret_cast<char*>(h), sizeof h)) return;
  if (std::memcmp(h, "\x89PNG\r\n\x1a\n", 8) != 0 || std::memcmp(h + 12, "IHDR", 4) != 0) return;
  auto be32 = [](const unsigned char* b) {
    return std::int64_t(b[0]) << 24 | std::int64_t(b[1]) << 16 | std::int64_t(b[2]) << 8 | b[3];
  };
  const std::int64_t w = be32(h + 16), ht = be32(h + 20);
  if (w > kMaxPixels || ht > kMaxPixels || w * ht > kMaxPixels)  // in this order: no overflow
    throw std::runtime_error("image '" + path + "' declares " + std::to_string(w) + "x" +
                             std::to_string(ht) + " pixels, more than the " +
                             std::to_string(kMaxPixels) + " accepted for one frame");
}

void refuseTruncatedJpeg(const std::string& path, const std::string& what) {
  std::ifstream in(path, std::ios::binary);
  const std::string b{std::istreambuf_iterator<char>(in), {}};
  auto at = [&](std::size_t i) { return static_cast<unsigned char>(b[i]); };
  if (b.size() < 4 || at(0) != 0xFF || at(1) != 0xD8) return;  // not a JPEG
  // The marker segments up to the first start of scan (FF DA), each FF <marker> <16-bit length>.
  std::size_t pos = 2;
  while (true) {
    if (pos + 4 > b.size() || at(pos) != 0xFF) return;  // not walkable: the decoder's to judge
    const unsigned char marker = at(pos + 1);
    if (marker == 0xDA) break;
    if (marker == 0xFF) {  // fill byte
      ++pos;
      continue;
    }
    pos += 2 + (std::size_t(at(pos + 2)) << 8 | at(pos + 3));
  }
  if (b.find("\xFF\xD9", pos) == std::string::npos)
    throw std::runtime_error(what + " image '" + path +
                             "' is a truncated JPEG file: its image data has no end-of-image "
                             "marker");
}

}  // namespace hrgbd
