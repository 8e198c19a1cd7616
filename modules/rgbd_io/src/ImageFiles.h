#pragma once
/** \file ImageFiles.h
 * Checks on an image file's bytes before a decoder sees it, for what OpenCV and MRPT decode
 * without an error: a size no frame has, a JPEG cut short. By hand: OpenCV 4.6 has no call that
 * reads an image's header without decoding it. */
#include <cstdint>
#include <string>

namespace hrgbd {

/** The largest frame read [pixels], above any RGB-D sensor's (4096x3072 colour at most): a
 * larger size declared in an image header is a corrupt or hostile file ("decompression bomb"). */
inline constexpr std::int64_t kMaxPixels = std::int64_t(4096) * 4096;

/** Throws std::runtime_error naming `path` when it is a PNG whose header (IHDR, which the format
 * puts first) declares more than kMaxPixels: refused before the decoder allocates them. */
void refuseHugePng(const std::string& path);

/** Throws std::runtime_error "<what> image '<path>' is a truncated JPEG file ..." when `path` is a
 * JPEG whose image data (from its first scan, found by walking the marker segments, so that an
 * EXIF thumbnail's are passed over) has no end-of-image marker (FF D9; it cannot occur inside the
 * compressed data, where FF is always escaped). OpenCV and MRPT decode such a file with only
 * libjpeg's warning on stderr, and grey where rows are missing. Bytes after the marker (padding,
 * appended data) are fine; a file whose segments cannot be walked is left to the decoder. */
void refuseTruncatedJpeg(const std::string& path, const std::string& what);

}  // namespace hrgbd
