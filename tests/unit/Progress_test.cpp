// Progress with an injected clock and stream: what is written and when, never how fast.
#include "rgbd_core/Progress.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

struct Fixture {
  std::ostringstream out;
  double now = 100;  // any origin
  hrgbd::Progress make(const hrgbd::ProgressParams& p) {
    return hrgbd::Progress(out, p, [this] { return now; });
  }
};

}  // namespace

TEST(Progress, LineShowsDoneTotalRateAndTimeLeft) {
  Fixture f;
  hrgbd::ProgressParams p;
  p.label = "real/teddy hybrid";
  p.total = 200;
  const auto progress = f.make(p);
  EXPECT_EQ(progress.text(50, 10),
            "real/teddy hybrid: 50/200 frames (25%), 5.0 frames/s, 30 s left");
  EXPECT_EQ(progress.text(0, 0), "real/teddy hybrid: 0/200 frames (0%)");
  EXPECT_EQ(progress.text(200, 40), "real/teddy hybrid: 200/200 frames (100%), 5.0 frames/s");
  p.label.clear();
  p.total = 0;  // a live sensor: no total, no time left
  EXPECT_EQ(f.make(p).text(50, 10), "50 frames, 5.0 frames/s");
}

TEST(Progress, DurationsReadAsMinutesAndHours) {
  EXPECT_EQ(hrgbd::formatDuration(4.44), "4.4 s");
  EXPECT_EQ(hrgbd::formatDuration(12.4), "12 s");
  EXPECT_EQ(hrgbd::formatDuration(125), "2 min 05 s");
  EXPECT_EQ(hrgbd::formatDuration(3725), "1 h 02 min");
  EXPECT_EQ(hrgbd::formatDuration(-3), "0.0 s");
}

TEST(Progress, OnATerminalOneLineIsRedrawnAtMostFourTimesASecond) {
  Fixture f;
  hrgbd::ProgressParams p;
  p.total = 10;
  p.terminal = true;
  auto progress = f.make(p);
  for (std::size_t i = 1; i <= 10; ++i) {
    f.now += 0.1;  // 10 frames/s: every third frame is due
    progress.update(i, i < 10 ? "long detail text" : "");
  }
  progress.finish();
  const auto s = f.out.str();
  EXPECT_EQ(std::count(s.begin(), s.end(), '\n'), 1) << "one line, ended once: " << s;
  EXPECT_EQ(s.back(), '\n');
  const auto redraws = std::count(s.begin(), s.end(), '\r');
  EXPECT_GE(redraws, 3);
  EXPECT_LE(redraws, 5);
  EXPECT_NE(s.find("\r1/10 frames (10%), 10.0 frames/s, 0.9 s left, long detail text"),
            std::string::npos)
      << s;
  // The final line clears what the longer line before it left on screen.
  const auto end = s.rfind('\r'), before = s.rfind('\r', end - 1);
  const auto last = s.substr(end + 1, s.size() - end - 2),
             previous = s.substr(before + 1, end - before - 1);
  EXPECT_EQ(last.rfind("10 frames in 1.0 s, 10.0 frames/s", 0), 0u) << last;
  EXPECT_EQ(previous.substr(0, previous.find_last_not_of(' ') + 1),
            "10/10 frames (100%), 10.0 frames/s");
  EXPECT_GE(last.size(), previous.size());
  EXPECT_EQ(last.find_last_not_of(' ') + 1,
            std::string("10 frames in 1.0 s, 10.0 frames/s").size());
  progress.finish();  // once only
  EXPECT_EQ(f.out.str(), s);
}

TEST(Progress, InAFileALineEveryTenPercentButNotMoreThanOncePerSecond) {
  Fixture f;
  hrgbd::ProgressParams p;
  p.total = 100;
  auto progress = f.make(p);
  for (std::size_t i = 1; i <= 100; ++i) {
    f.now += i <= 50 ? 0.25 : 0.0625;  // 12.5 s, then 3.125 s for the second half
    progress.update(i);
  }
  progress.finish();
  const auto l = lines(f.out.str());
  // 10 % ... 50 %: 2.5 s apart; then a further 10 % comes every 0.625 s: a line once 1 s passed.
  ASSERT_EQ(l.size(), 9u) << f.out.str();
  EXPECT_EQ(l[0], "10/100 frames (10%), 4.0 frames/s, 23 s left");
  EXPECT_EQ(l[4].rfind("50/100 frames (50%)", 0), 0u) << l[4];
  EXPECT_EQ(l[5].rfind("66/100 frames (66%)", 0), 0u) << l[5];
  EXPECT_EQ(l[6].rfind("82/100 frames (82%)", 0), 0u) << l[6];
  EXPECT_EQ(l[7].rfind("98/100 frames (98%)", 0), 0u) << l[7];
  EXPECT_EQ(l[8], "100 frames in 16 s, 6.4 frames/s");
  EXPECT_EQ(f.out.str().find('\r'), std::string::npos);
}

TEST(Progress, InAFileWithoutTotalALineEveryTenSeconds) {
  Fixture f;
  hrgbd::ProgressParams p;
  p.unit = "images";
  auto progress = f.make(p);
  for (std::size_t i = 1; i <= 200; ++i) {
    f.now += 0.125;  // 25 s in all, in steps a double holds exactly
    progress.update(i);
  }
  const auto l = lines(f.out.str());
  ASSERT_EQ(l.size(), 2u) << f.out.str();
  EXPECT_EQ(l[0], "80 images, 8.0 images/s");
  EXPECT_EQ(l[1], "160 images, 8.0 images/s");
}

TEST(Progress, TimeLeftSaysWhatFollowsTheLastItem) {
  Fixture f;
  hrgbd::ProgressParams p;
  p.total = 200;
  p.after = "final steps";
  const auto progress = f.make(p);
  EXPECT_EQ(progress.text(50, 10), "50/200 frames (25%), 5.0 frames/s, 30 s left + final steps");
  EXPECT_EQ(progress.text(200, 40), "200/200 frames (100%), 5.0 frames/s");
}

TEST(StagedProgress, OneLineAStageEachFinishedWhenTheNextBegins) {
  std::ostringstream out;
  double now = 0;
  hrgbd::StagedProgress stages(out, false, [&] { return now; });
  stages.update("seeding", "words", 1, 4);
  now = 2;
  stages.update("seeding", "words", 4, 4);
  stages.update("k-majority", "rounds", 1, 15);
  now = 5;
  stages.update("k-majority", "rounds", 3, 15);
  stages.finish();
  // in a file: no line in the first second of a stage, the final line of each
  const auto l = lines(out.str());
  ASSERT_EQ(l.size(), 3u) << out.str();
  EXPECT_EQ(l[0], "seeding: 4 words in 2.0 s, 2.0 words/s");
  EXPECT_EQ(l[1], "k-majority: 3/15 rounds (20%), 1.0 rounds/s, 12 s left");
  EXPECT_EQ(l[2], "k-majority: 3 rounds in 3.0 s, 1.0 rounds/s");
}

TEST(TimedStep, LineBeginsBeforeTheStepAndEndsWithItsTime) {
  std::ostringstream out;
  double now = 10;
  std::string seen_during;
  hrgbd::timedStep(
      out, "writing the map",
      [&] {
        seen_during = out.str();
        now += 1.25;
      },
      [&] { return now; });
  EXPECT_EQ(seen_during, "writing the map ... ");
  EXPECT_EQ(out.str(), "writing the map ... 1.2 s\n");
  out.str("");
  EXPECT_THROW(
      hrgbd::timedStep(
          out, "writing x", [] { throw std::runtime_error("disk full"); }, [&] { return now; }),
      std::runtime_error);
  EXPECT_EQ(out.str(), "writing x ... failed\n");
}
