#pragma once
/** \file Timestamp.h
 * Frame time stamps: MRPT's clock and their text in TUM files.
 *
 * A frame carries its time stamp as an mrpt::Clock::time_point (100 ns ticks), whose conversion
 * to seconds (mrpt::Clock::toDouble, used by the odometry) is only right from 1970 on, and whose
 * conversion from seconds (fromDouble) wraps or gives 0 outside that range. Frame time stamps
 * are therefore seconds of UNIX time in [0, kMaxFrameSeconds) at the clock's 100 ns resolution;
 * anything else is refused with the reason, never turned into another time. Their text is read
 * exactly (from the decimal digits, not through a double) and written exactly with 9 decimals,
 * so a stamp goes from rgb.txt or a rawlog to the trajectory and CSV unchanged.
 * Time stamps held as doubles (ground-truth files) are written in the shortest text that reads
 * back as the same double (formatSeconds()). */
#include <mrpt/core/Clock.h>

#include <string>

namespace hrgbd {

/** [s] Frame time stamps are below this: 1e11 s of UNIX time is about the year 5138. It refuses
 * time stamps in ms, us or ns (ROS-style 19-digit stamps) taken for seconds. */
inline constexpr double kMaxFrameSeconds = 1e11;

/** Parses one frame time stamp in seconds ("1305031453.359684", also "1.5e3") exactly. Throws
 * std::invalid_argument saying why for text that is not a number, a negative or too large stamp,
 * or digits finer than 100 ns; callers add the file and line. */
mrpt::Clock::time_point parseFrameTime(const std::string& text);

/** Throws std::invalid_argument saying why unless `t` lies in [0, kMaxFrameSeconds) s (an unset
 * MRPT time stamp lies before 1970). For time stamps read from rawlogs. */
void checkFrameTime(mrpt::Clock::time_point t);

/** The frame time stamp nearest to `seconds` (rounded to 100 ns); throws std::invalid_argument
 * outside [0, kMaxFrameSeconds) s. For computed times (the simulator's). */
mrpt::Clock::time_point frameTimeFromSeconds(double seconds);

/** [s] UNIX time of a frame time stamp (mrpt::Clock::toDouble(), right for any time_point). */
double frameSeconds(mrpt::Clock::time_point t);

/** The exact text of a frame time stamp with 9 decimals, e.g. "1305031453.359684000". */
std::string formatFrameTime(mrpt::Clock::time_point t);

/** The shortest text that reads back as exactly `seconds` ("2.5", "1305031453.3596", "1e+300"). */
std::string formatSeconds(double seconds);

}  // namespace hrgbd
