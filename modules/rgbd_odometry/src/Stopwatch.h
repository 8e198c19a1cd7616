#pragma once
// Private: per-stage timing of the odometry (milliseconds since a time point).
#include <chrono>

namespace hrgbd {

using Clock = std::chrono::steady_clock;

inline double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

}  // namespace hrgbd
