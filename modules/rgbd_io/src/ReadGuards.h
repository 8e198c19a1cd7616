#pragma once
/** \file ReadGuards.h
 * Where MRPT 2.5 ends or crashes the program on a corrupt rawlog, make it throw instead, so the
 * rawlog reader can name the file and entry (see ReadGuards.cpp). */
#include <string>

namespace hrgbd {
/** Call where rawlogs are read: it makes the linker keep the interposers of ReadGuards.cpp. */
void installReadGuards();

/** While one exists on a thread, MRPT containers allocated there may not exceed 1 GiB each: a
 * bigger one can only come from a corrupt length field in the rawlog entry being read. */
class ReadingRawlogEntry {
 public:
  ReadingRawlogEntry();
  ~ReadingRawlogEntry();
  ReadingRawlogEntry(const ReadingRawlogEntry&) = delete;
  ReadingRawlogEntry& operator=(const ReadingRawlogEntry&) = delete;
};

/** Throws std::runtime_error "<what> image '<path>' is a truncated JPEG file ..." when `path`
 * starts as a JPEG (FF D8) but has no end-of-image marker (FF D9) in its last 1 KiB. OpenCV and
 * MRPT decode such a file with only libjpeg's warning on stderr, and grey where rows are missing.
 * (The marker cannot occur inside the compressed data, where FF is always escaped.) */
void refuseTruncatedJpeg(const std::string& path, const std::string& what);
}  // namespace hrgbd
