#pragma once
/** \file TumLists.h
 * TUM RGB-D list files (`rgb.txt`, `depth.txt`: "timestamp filename") and their association. */
#include <mrpt/core/Clock.h>

#include <string>
#include <vector>

namespace hrgbd {

/** One entry of a TUM list file. */
struct TumListEntry {
  double t = 0;                   //!< [s]
  mrpt::Clock::time_point stamp;  //!< the same, exactly as written (Timestamp.h)
  std::string file;               //!< path relative to the dataset folder
  int line = 0;                   //!< line number in the list file, for messages
};

/** Parses a TUM list. Comments ('#'), blank lines and a UTF-8 byte-order mark are skipped. Throws
 * std::runtime_error naming the file and line for a malformed line, a time stamp that is no frame
 * time (parseFrameTime(): negative, not below 1e11 s, finer than 100 ns, not a number), or one that
 * is not strictly greater than the previous one (duplicated or out-of-order stamps). */
std::vector<TumListEntry> parseTumList(const std::string& path);

/** Same, from text already in memory; `name` is used in messages. */
std::vector<TumListEntry> parseTumListText(const std::string& text, const std::string& name);

/** The pinhole intrinsics of a folder's `calibration.txt` (the ETH3D SLAM benchmark's RGB-D
 * folders: "fx fy cx cy" in pixels on one line). */
struct TumCalibration {
  double fx = 0, fy = 0, cx = 0, cy = 0;  //!< [px]
};

/** Parses a calibration.txt: one line of four finite numbers, fx and fy positive;
 * comments ('#') and blank lines skipped. Throws std::runtime_error naming the file and line for
 * anything else (fewer or more numbers, a second line of numbers, text). */
TumCalibration parseTumCalibrationText(const std::string& text, const std::string& name);

/** A colour/depth pair matched by time. */
struct TumPair {
  TumListEntry rgb, depth;
};

/** Associates colour and depth entries as TUM's associate.py does: candidate pairs closer than
 * `max_dt` [s], taken greedily by increasing time difference, each entry used once; the result
 * is sorted by colour time (see associateByTime()). */
std::vector<TumPair> associateTumLists(const std::vector<TumListEntry>& rgb,
                                       const std::vector<TumListEntry>& depth, double max_dt);

}  // namespace hrgbd
