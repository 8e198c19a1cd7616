#pragma once
/** \file Trajectory.h
 * Camera trajectories in the TUM RGB-D format and the frame conventions around them.
 *
 * Conventions:
 * - TUM poses (`timestamp tx ty tz qx qy qz qw`) are the pose of the colour camera's
 *   *optical* frame (z forward, x right, y down) in a world frame; so are all poses in
 *   `Trajectory`.
 * - MRPT's CObservation3DRangeScan sensor frame is x forward, y left, z up. A sensor pose in
 *   MRPT's convention (e.g. `CObservation3DRangeScan::sensorPose`) relates to the optical pose by
 *   `mrpt_pose = optical_pose (+) kOpticalToMrpt` (see opticalToMrpt()).
 */
#include <mrpt/poses/CPose3D.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace hrgbd {

/** [m] Positions are evaluated (and replayed by the simulator) up to this far from the origin
 * (UTM coordinates fit): beyond it a double's step exceeds 0.1 um and the squares of the
 * alignment lose the figures. */
inline constexpr double kMaxTrajectoryCoordinate = 1e9;

/** One pose with its time stamp [s, UNIX time as in TUM files]. */
struct TimedPose {
  double t = 0;
  mrpt::poses::CPose3D pose;
};
using Trajectory = std::vector<TimedPose>;

/** Reads a TUM trajectory file. Lines starting with '#', blank lines and a UTF-8 byte-order mark
 * are skipped. Throws std::runtime_error naming the file and line for a malformed line, a
 * non-finite value or a zero quaternion, naming the file when it is missing or a folder, and, with
 * `unique_times`, for a time stamp already given on an earlier line (TUM ground truth may repeat
 * one: the original fr2/desk file does). Quaternions are normalised. Entries are returned in file
 * order. */
Trajectory loadTumTrajectory(const std::string& path, bool unique_times = false);

/** Writes one TUM line (`t tx ty tz qx qy qz qw`): t as formatSeconds() writes it (the shortest
 * text that reads back as the same double), the rest with 6 decimals. */
void writeTumLine(std::ostream& out, const TimedPose& p);

/** Same with the time stamp's text given (e.g. formatFrameTime() of a frame's exact stamp). */
void writeTumLine(std::ostream& out, const std::string& time, const mrpt::poses::CPose3D& pose);

/** Writes a whole trajectory with a '#' header comment, in full or not at all (OutputFile.h);
 * throws naming the file if it cannot be written. */
void saveTumTrajectory(const std::string& path, const Trajectory& traj);

/** Pose of MRPT's sensor frame (x fwd, y left, z up) relative to the optical frame (z fwd,
 * x right, y down). Equals CPose3D(0,0,0, -90deg, 0, -90deg)^-1 ... see opticalToMrpt(). */
mrpt::poses::CPose3D mrptFrameInOptical();

/** Optical-frame pose (TUM) -> the same camera's pose in MRPT's sensor convention. */
mrpt::poses::CPose3D opticalToMrpt(const mrpt::poses::CPose3D& optical_pose);

/** MRPT sensor-convention pose -> optical-frame pose (TUM); inverse of opticalToMrpt(). */
mrpt::poses::CPose3D mrptToOptical(const mrpt::poses::CPose3D& mrpt_pose);

/** A trajectory pose (optical frame, relative to the first camera's optical frame) -> the
 * camera's MRPT-convention pose in an MRPT world: the first camera's MRPT frame (x forward,
 * z up when that camera was level). Maps, frustums and rawlog sensor poses use this world. */
mrpt::poses::CPose3D opticalToMrptWorld(const mrpt::poses::CPose3D& optical_pose);

/** Inverse of opticalToMrptWorld(). */
mrpt::poses::CPose3D mrptWorldToOptical(const mrpt::poses::CPose3D& mrpt_world_pose);

}  // namespace hrgbd
