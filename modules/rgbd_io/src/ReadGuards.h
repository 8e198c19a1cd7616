#pragma once
/** \file ReadGuards.h
 * Where MRPT 2.5 ends or crashes the program on a corrupt rawlog, make it throw instead, so the
 * rawlog reader can name the file and entry (see ReadGuards.cpp). */
namespace hrgbd {
/** Call where rawlogs are read: it makes the linker keep the interposers of ReadGuards.cpp. */
void installReadGuards();
}  // namespace hrgbd
