// The concrete frame sinks: what each writes or keeps for a given sequence of results.
#include <algorithm>
#include <fstream>
#include <sstream>

#include "TestData.h"
#include "rgbd_app/MapSinks.h"
#include "rgbd_app/TextSinks.h"
#include "rgbd_io/RawlogSource.h"

namespace {

const std::string kDesk = std::string(HRGBD_SOURCE_DIR) + "/rawlogs/desk_near.rawlog";

std::vector<std::string> lines(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

hrgbd::FrameResult result(double t, double x, hrgbd::FrameResult::Status s) {
  hrgbd::FrameResult r;
  r.t = t;
  r.pose = mrpt::poses::CPose3D(x, 0, 0, 0, 0, 0);
  r.status = s;
  return r;
}

constexpr auto kOk = hrgbd::FrameResult::Status::Ok;
constexpr auto kLost = hrgbd::FrameResult::Status::TooFewMatches;

}  // namespace

TEST(TrajectorySink, WritesAndFlushesOneTumLinePerFrame) {
  const auto dir = hrgbd::test::tempDir("trajectory_sink");
  hrgbd::RawlogSource src(kDesk);
  const auto obs = src.next();
  hrgbd::TrajectorySink sink(dir + "/t.txt", "# comment");
  sink.add(*obs, result(1.5, 0.25, kOk));
  sink.add(*obs, result(2.5, 0.5, kLost));
  // Readable while the sink is open: each line is flushed as written.
  const auto text = lines(dir + "/t.txt");
  ASSERT_EQ(text.size(), 3u);
  EXPECT_EQ(text[0], "# comment");
  EXPECT_EQ(text[2], "2.500000000 0.500000 0.000000 0.000000 0.000000 0.000000 0.000000 1.000000");
  ASSERT_EQ(sink.trajectory().size(), 2u);
  sink.reset();
  EXPECT_TRUE(sink.trajectory().empty());
  EXPECT_EQ(lines(dir + "/t.txt").size(), 3u);  // the file keeps what it has
  EXPECT_THROW(hrgbd::TrajectorySink(dir + "/no/such/folder/t.txt", "#"), std::runtime_error);
}

TEST(CsvSink, OneFlushedRowPerFrameWithTheHeadersColumns) {
  const auto dir = hrgbd::test::tempDir("csv_sink");
  hrgbd::RawlogSource src(kDesk);
  const auto obs = src.next();
  hrgbd::CsvSink sink(dir + "/f.csv");
  auto r = result(1.5, 0.25, kLost);
  r.detail = "only 3 matches";
  sink.add(*obs, r);
  const auto text = lines(dir + "/f.csv");
  ASSERT_EQ(text.size(), 2u);
  const auto commas = [](const std::string& s) { return std::count(s.begin(), s.end(), ','); };
  EXPECT_EQ(commas(text[0]), commas(text[1]));
  EXPECT_EQ(text[1].rfind("1.500000,too_few_matches,photometric,", 0), 0u) << text[1];
  EXPECT_NE(text[1].find("\"only 3 matches\""), std::string::npos);
}

TEST(ColouredMapSink, OnlyRegisteredFramesEnterTheMapEveryFrameThePath) {
  const auto dir = hrgbd::test::tempDir("map_sink");
  hrgbd::RawlogSource src(kDesk);
  const auto obs = src.next();
  hrgbd::ColouredMapSink sink(hrgbd::MapParams(), {dir + "/m.ply", ""});
  sink.add(*obs, result(1, 0, kLost));
  EXPECT_EQ(sink.map().size(), 0u);
  EXPECT_EQ(sink.path().size(), 1u);
  sink.add(*obs, result(2, 0.1, kOk));
  const auto points = sink.map().size();
  EXPECT_GT(points, 1000u);
  ASSERT_EQ(sink.path().size(), 2u);
  // The path is in the MRPT world: optical z forward is MRPT x forward, optical x right is -y.
  EXPECT_NEAR(sink.path()[1].y(), -0.1, 1e-9);
  std::ostringstream log;
  sink.finish(log);
  EXPECT_EQ(log.str(), "map (PLY, " + std::to_string(points) + " points): " + dir + "/m.ply\n");
  const auto ply = lines(dir + "/m.ply");
  EXPECT_NE(std::find(ply.begin(), ply.end(), "element vertex " + std::to_string(points)),
            ply.end());
  sink.reset();
  EXPECT_EQ(sink.map().size(), 0u);
  EXPECT_TRUE(sink.path().empty());
}

TEST(ProgressSink, RedrawsOneLineAndEndsIt) {
  hrgbd::RawlogSource src(kDesk);
  const auto obs = src.next();
  std::ostringstream out, log;
  hrgbd::ProgressSink sink(out);
  sink.add(*obs, result(1, 0, kOk));
  sink.add(*obs, result(2, 0, kLost));
  sink.finish(log);
  EXPECT_EQ(out.str().back(), '\n');
  EXPECT_NE(out.str().rfind("\r  frame      2  registered      1"), std::string::npos) << out.str();
  EXPECT_TRUE(log.str().empty());
}
