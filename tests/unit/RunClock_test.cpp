// The benchmark's time left (RunClock, private to rgbd_bench): each method's seconds per frame
// times the frames of the runs left.
#include <gtest/gtest.h>

#include "../../modules/rgbd_bench/src/Runs.h"  // (private to rgbd_bench)

TEST(RunClock, TimeLeftIsEachMethodsRateTimesTheFramesOfTheRunsLeft) {
  hrgbd::bench::RunClock clock;
  EXPECT_LT(clock.secondsLeft({{"sim/a", "hybrid"}}), 0) << "nothing known yet";
  clock.expect("real/long", 200);
  clock.add("sim/a", "hybrid", 30, 3.0);       // 0.1 s a frame
  clock.add("sim/a", "opencv_rgbd", 30, 1.5);  // 0.05 s a frame
  EXPECT_DOUBLE_EQ(clock.secondsLeft({}), 0);
  // the counted frames of a sequence, each method at its own rate
  EXPECT_DOUBLE_EQ(clock.secondsLeft({{"real/long", "hybrid"}, {"real/long", "opencv_rgbd"}}),
                   200 * 0.1 + 200 * 0.05);
  // a method not run yet: the rate of all; a sequence not counted: the mean of those known
  EXPECT_DOUBLE_EQ(clock.secondsLeft({{"sim/b", "ransac"}}), (30 + 200) / 2.0 * 4.5 / 60);
}
