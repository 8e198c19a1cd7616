#include "rgbd_core/Trajectory.h"

#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/CQuaternion.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>
#include <stdexcept>

#include "rgbd_core/OutputFile.h"
#include "rgbd_core/TextFile.h"
#include "rgbd_core/Timestamp.h"

namespace hrgbd {

Trajectory loadTumTrajectory(const std::string& path, bool unique_times) {
  std::istringstream in(readTextFile(path, "trajectory file"));
  Trajectory traj;
  std::map<double, int> lines;  // time stamp -> line, with unique_times
  std::string line;
  for (int line_no = 1; std::getline(in, line); ++line_no) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream ss(line);
    double v[8];
    for (double& x : v) ss >> x;
    const auto where = "'" + path + "' line " + std::to_string(line_no);
    if (ss.fail())
      throw std::runtime_error(where + ": expected 8 numbers 't tx ty tz qx qy qz qw'");
    if (!(ss >> std::ws).eof()) {
      // More columns: another format, whose first 8 numbers would be read as wrong poses.
      std::istringstream all(line);
      std::size_t n = 0;
      for (std::string word; all >> word;) ++n;
      throw std::runtime_error(
          where + ": " + std::to_string(n) + " columns" +
          (n == 12 ? ": KITTI format (a 3x4 matrix per line, no time stamp), not TUM" : "") +
          "; a TUM trajectory has 8 numbers a line 't tx ty tz qx qy qz qw'");
    }
    for (double x : v)
      if (!std::isfinite(x)) throw std::runtime_error(where + ": non-finite value");
    // Norm scaled by the largest component: squares of 1e200 overflow (found by fuzz_tum_list).
    const double m = std::max({std::abs(v[4]), std::abs(v[5]), std::abs(v[6]), std::abs(v[7])});
    const double qnorm = m == 0 ? 0
                                : m * std::sqrt(std::pow(v[4] / m, 2) + std::pow(v[5] / m, 2) +
                                                std::pow(v[6] / m, 2) + std::pow(v[7] / m, 2));
    if (qnorm < 1e-9) throw std::runtime_error(where + ": zero quaternion");
    if (unique_times) {
      const auto [it, inserted] = lines.emplace(v[0], line_no);
      if (!inserted)
        throw std::runtime_error(where + ": time stamp " + formatSeconds(v[0]) +
                                 " was already given on line " + std::to_string(it->second) +
                                 "; a trajectory has one pose per time");
    }
    mrpt::math::CQuaternionDouble q(v[7] / qnorm, v[4] / qnorm, v[5] / qnorm, v[6] / qnorm);
    traj.push_back({v[0], mrpt::poses::CPose3D(q, v[1], v[2], v[3])});
  }
  return traj;
}

void writeTumLine(std::ostream& out, const std::string& time, const mrpt::poses::CPose3D& pose) {
  mrpt::math::CQuaternionDouble q;
  pose.getAsQuaternion(q);
  out << time << std::fixed << std::setprecision(6) << " " << pose.x() << " " << pose.y() << " "
      << pose.z() << " " << q.x() << " " << q.y() << " " << q.z() << " " << q.r() << "\n";
}

void writeTumLine(std::ostream& out, const TimedPose& p) {
  writeTumLine(out, formatSeconds(p.t), p.pose);
}

void saveTumTrajectory(const std::string& path, const Trajectory& traj) {
  StreamOutput out(path, "trajectory file");
  out.stream() << "# timestamp tx ty tz qx qy qz qw (optical frame: z forward, x right, y down)\n";
  for (const auto& p : traj) writeTumLine(out.stream(), p);
  out.commit();
}

mrpt::poses::CPose3D mrptFrameInOptical() {
  // Columns: MRPT x (forward) = optical +z, MRPT y (left) = optical -x, MRPT z (up) = optical -y.
  const double rows[9] = {0, -1, 0, 0, 0, -1, 1, 0, 0};
  const mrpt::math::CMatrixDouble33 R(rows);
  return mrpt::poses::CPose3D::FromRotationAndTranslation(R, mrpt::math::TVector3D(0, 0, 0));
}

mrpt::poses::CPose3D opticalToMrpt(const mrpt::poses::CPose3D& optical_pose) {
  return optical_pose + mrptFrameInOptical();
}

mrpt::poses::CPose3D mrptToOptical(const mrpt::poses::CPose3D& mrpt_pose) {
  return mrpt_pose + (-mrptFrameInOptical());  // a (+) b^-1; note MRPT a - b = b^-1 (+) a
}

mrpt::poses::CPose3D opticalToMrptWorld(const mrpt::poses::CPose3D& optical_pose) {
  return (-mrptFrameInOptical()) + opticalToMrpt(optical_pose);
}

mrpt::poses::CPose3D mrptWorldToOptical(const mrpt::poses::CPose3D& mrpt_world_pose) {
  return mrptToOptical(mrptFrameInOptical() + mrpt_world_pose);
}

}  // namespace hrgbd
