// The frame loop: every frame reaches every sink, in order, with the odometry's result; max_frames
// and reset() behave as the live app and playback rely on.
#include "rgbd_app/FrameLoop.h"

#include <mrpt/config/CConfigFileMemory.h>

#include <sstream>

#include "TestData.h"
#include "rgbd_app/TextSinks.h"
#include "rgbd_app/makeOdometry.h"
#include "rgbd_core/RgbdFrame.h"
#include "rgbd_io/RawlogSource.h"

namespace {

const std::string kDesk = std::string(HRGBD_SOURCE_DIR) + "/rawlogs/desk_near.rawlog";

/** Records what it is given; `order` is shared between sinks to check the call order. */
struct FakeSink : hrgbd::FrameSink {
  FakeSink(int id_, std::vector<int>& order_) : id(id_), order(order_) {}
  void add(const mrpt::obs::CObservation3DRangeScan& obs, const hrgbd::FrameResult& r) override {
    obs_t.push_back(hrgbd::timestampSeconds(obs));
    results.push_back(r);
    order.push_back(id);
  }
  void finish(std::ostream& log) override { log << "fake " << id << " finished\n"; }
  void reset() override { ++resets; }
  int id;
  std::vector<int>& order;
  std::vector<double> obs_t;
  std::vector<hrgbd::FrameResult> results;
  int resets = 0;
};

std::unique_ptr<hrgbd::RgbdOdometry> odometry() {
  return hrgbd::makeOdometry(hrgbd::OdometryParams(), mrpt::config::CConfigFileMemory());
}

}  // namespace

TEST(FrameLoop, SinksSeeEveryFrameInOrderWithTheTrajectoryFilesPoses) {
  const auto dir = hrgbd::test::tempDir("frame_loop");
  hrgbd::RawlogSource source(kDesk);
  std::vector<int> order;
  FakeSink first(1, order), second(2, order);
  hrgbd::TrajectorySink trajectory(dir + "/traj.txt", "# test");
  hrgbd::FrameLoop loop(source, odometry(), {&first, &trajectory, &second}, 7);
  EXPECT_EQ(loop.run(), 7u);
  EXPECT_FALSE(loop.step());  // max_frames reached: nothing more is read
  EXPECT_EQ(source.stats().frames, 7u);
  std::ostringstream log;
  loop.finish(log);
  // in order; the trajectory's a timed step ("... 0.0 s")
  const auto text = log.str(), end = std::string(" s\nfake 2 finished\n");
  EXPECT_EQ(text.rfind("fake 1 finished\ntrajectory: " + dir + "/traj.txt ... ", 0), 0u) << text;
  ASSERT_GT(text.size(), end.size());
  EXPECT_EQ(text.substr(text.size() - end.size()), end) << text;

  // The rawlog's first 7 frames, in order, each to sink 1 then sink 2.
  hrgbd::RawlogSource again(kDesk);
  ASSERT_EQ(first.results.size(), 7u);
  for (std::size_t i = 0; i < 7; ++i) {
    EXPECT_DOUBLE_EQ(first.obs_t[i], hrgbd::timestampSeconds(*again.next())) << i;
    EXPECT_DOUBLE_EQ(first.results[i].t, first.obs_t[i]) << i;
    EXPECT_EQ(second.results[i].pose, first.results[i].pose) << i;
    EXPECT_EQ(order[2 * i], 1);
    EXPECT_EQ(order[2 * i + 1], 2);
  }
  EXPECT_EQ(first.results[0].status, hrgbd::FrameResult::Status::FirstFrame);
  EXPECT_GT(first.results.back().pose.norm(), 0.005);  // the camera moved: poses are not trivial

  // The trajectory file holds the same poses (6 decimals) and time stamps (9 decimals).
  const auto file = hrgbd::loadTumTrajectory(dir + "/traj.txt");
  ASSERT_EQ(file.size(), 7u);
  for (std::size_t i = 0; i < 7; ++i) {
    EXPECT_NEAR(file[i].t, first.results[i].t, 1e-9) << i;
    EXPECT_LT((file[i].pose.asVectorVal() - first.results[i].pose.asVectorVal()).norm(), 1e-5) << i;
  }
  EXPECT_EQ(trajectory.trajectory().size(), 7u);
}

TEST(FrameLoop, RunsToTheEndOfTheData) {
  hrgbd::RawlogSource source(kDesk);
  std::vector<int> order;
  FakeSink sink(1, order);
  hrgbd::FrameLoop loop(source, odometry(), {&sink});
  EXPECT_EQ(loop.run(), 20u);
  EXPECT_FALSE(loop.step());
  EXPECT_EQ(sink.results.size(), 20u);
}

TEST(FrameLoop, ResetMakesTheNextFrameTheOriginAndRestartsTheFrameCount) {
  hrgbd::RawlogSource source(kDesk);
  std::vector<int> order;
  FakeSink sink(1, order);
  hrgbd::FrameLoop loop(source, odometry(), {&sink}, 5);
  EXPECT_EQ(loop.run(), 5u);
  ASSERT_GT(sink.results.back().pose.norm(), 0.001);
  loop.reset();
  EXPECT_EQ(sink.resets, 1);
  EXPECT_EQ(loop.frames(), 0u);
  ASSERT_TRUE(loop.step());
  EXPECT_EQ(sink.results.back().status, hrgbd::FrameResult::Status::FirstFrame);
  EXPECT_EQ(sink.results.back().pose, mrpt::poses::CPose3D());
  // max_frames counts again from the reset: 4 more frames, then it stops.
  EXPECT_EQ(loop.run(), 5u);
  EXPECT_EQ(sink.results.size(), 10u);
  EXPECT_EQ(source.stats().frames, 10u);
}
