#pragma once
/** \file ReadGuards.h
 * Where MRPT 2.5 ends or crashes the program on a corrupt rawlog, make it throw instead, so the
 * rawlog reader can name the file and entry (see ReadGuards.cpp). */
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
}  // namespace hrgbd
