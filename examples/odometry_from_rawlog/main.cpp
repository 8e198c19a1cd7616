// Runs the odometry (default parameters) over a rawlog and prints one TUM line per frame,
// `t tx ty tz qx qy qz qw`: the colour camera's pose in the first frame's optical frame.
// Frames that could not be registered are named on stderr with their status.
#include <mrpt/math/CQuaternion.h>
#include <rgbd_io/RawlogSource.h>
#include <rgbd_odometry/RgbdOdometry.h>

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s FILE.rawlog\n", argv[0]);
    return 2;
  }
  try {
    hrgbd::RawlogSource source(argv[1]);
    hrgbd::RgbdOdometry odometry(hrgbd::OdometryParams{});
    while (const auto obs = source.next()) {
      const hrgbd::FrameResult r = odometry.processObservation(*obs);
      mrpt::math::CQuaternionDouble q;
      r.pose.getAsQuaternion(q);
      std::printf("%.9f %.6f %.6f %.6f %.6f %.6f %.6f %.6f\n", r.t, r.pose.x(), r.pose.y(),
                  r.pose.z(), q.x(), q.y(), q.z(), q.r());
      if (!r.registered()) std::fprintf(stderr, "%.9f: %s\n", r.t, hrgbd::toString(r.status));
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
