// The grabber, the one path of a live sensor and of a recording played as one: a consumer slower
// than the frames drops some, one that keeps up drops none, a recording not played as a sensor
// loses nothing; order, ground truth and the source's error come through.
#include "rgbd_io/Grabber.h"

#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>
#include <thread>

#include "rgbd_core/RgbdFrame.h"

namespace {

using Clock = std::chrono::steady_clock;

// `n` frames 1/30 s apart from t = 100 s, read at once; throws at frame `fail_at` if >= 0.
class FakeSource : public hrgbd::FrameSource {
 public:
  explicit FakeSource(int n, int fail_at = -1) : m_n(n), m_fail_at(fail_at) {}
  mrpt::obs::CObservation3DRangeScan::Ptr next() override {
    if (m_i == m_fail_at) throw std::runtime_error("fake: frame " + std::to_string(m_i) + " bad");
    if (m_i >= m_n) return nullptr;
    auto obs = mrpt::obs::CObservation3DRangeScan::Create();
    obs->timestamp = mrpt::Clock::fromDouble(100.0 + m_i++ / 30.0);
    ++m_stats.frames;
    ++m_stats.skipped_objects;  // one other object before each frame
    return obs;
  }
  hrgbd::Trajectory groundTruth() const override { return {{100.0, mrpt::poses::CPose3D()}}; }
  std::string describe() const override { return "fake"; }

 private:
  int m_n, m_fail_at, m_i = 0;
};

struct Delivered {
  std::vector<double> t;
  double seconds = 0;
};

// Takes every frame, spending `ms` on each as a tracker would.
Delivered consume(hrgbd::Grabber& g, int ms) {
  Delivered d;
  const auto start = Clock::now();
  while (auto obs = g.next()) {
    d.t.push_back(hrgbd::timestampSeconds(*obs));
    std::this_thread::sleep_for(std::chrono::milliseconds(ms));
  }
  d.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return d;
}

void expectInOrder(const std::vector<double>& t) {
  for (std::size_t i = 1; i < t.size(); ++i) EXPECT_LT(t[i - 1], t[i]) << "frame " << i;
}

}  // namespace

TEST(Grabber, ATrackerSlowerThanTheFramesLosesSomeAsWithASensor) {
  hrgbd::Grabber g(std::make_unique<FakeSource>(30), true, 1.0);
  const auto d = consume(g, 100);  // 10 Hz against 30 Hz
  EXPECT_GT(g.dropped(), 10u);
  EXPECT_EQ(d.t.size() + g.dropped(), 30u);
  expectInOrder(d.t);
  ASSERT_FALSE(d.t.empty());
  EXPECT_NEAR(d.t.back(), 100.0 + 29 / 30.0, 1e-6);  // the newest frame is never the one dropped
}

TEST(Grabber, ATrackerThatKeepsUpLosesNone) {
  // at a quarter of the recorded speed (7.5 Hz): a drop needs the consumer 2 frames (267 ms)
  // behind, which a loaded machine running sanitized tests side by side does not reach
  hrgbd::Grabber g(std::make_unique<FakeSource>(10), true, 0.25);
  const auto d = consume(g, 0);
  EXPECT_EQ(g.dropped(), 0u);
  EXPECT_EQ(d.t.size(), 10u);
  expectInOrder(d.t);
  // on the time stamps: the last frame 9/30 s after the first, at a quarter of the speed
  EXPECT_GE(d.seconds, 4 * 9 / 30.0 - 0.05);
}

TEST(Grabber, ARecordingNotPlayedAsASensorWaitsForTheTracker) {
  hrgbd::Grabber g(std::make_unique<FakeSource>(20), false, 0);
  const auto d = consume(g, 10);
  EXPECT_EQ(g.dropped(), 0u);
  EXPECT_EQ(d.t.size(), 20u);
  expectInOrder(d.t);
}

TEST(Grabber, StopsReadingWhenTheConsumerIsDoneAndCountsItsLimit) {
  // at most 12 of 30 frames read, whatever is delivered or dropped
  hrgbd::Grabber limited(std::make_unique<FakeSource>(30), true, 0, 12);
  const auto d = consume(limited, 1);
  EXPECT_EQ(d.t.size() + limited.dropped(), 12u);
  // stopped after two frames, it reads no more: the count of drops stays where it was
  hrgbd::Grabber g(std::make_unique<FakeSource>(30), true, 1.0);
  ASSERT_TRUE(g.next());
  ASSERT_TRUE(g.next());
  g.stop();
  const auto dropped = g.dropped();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // 6 frames' time
  EXPECT_EQ(g.dropped(), dropped);
  EXPECT_LE(dropped, 1u);
}

TEST(Grabber, ForwardsGroundTruthCountsAndTheSourcesError) {
  hrgbd::Grabber g(std::make_unique<FakeSource>(10, 4), true, 0);
  EXPECT_EQ(g.groundTruth().size(), 1u);
  EXPECT_EQ(g.describe(), "fake");
  int frames = 0;
  try {
    while (g.next()) ++frames;
    FAIL() << "the source's error was not rethrown";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "fake: frame 4 bad");
  }
  EXPECT_EQ(frames + g.dropped(), 4u);
  EXPECT_EQ(g.stats().skipped_objects, 4u);
}
