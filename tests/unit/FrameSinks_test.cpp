// The concrete frame sinks: what each writes or keeps for a given sequence of results.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "TestData.h"
#include "rgbd_app/MapSinks.h"
#include "rgbd_app/TextSinks.h"
#include "rgbd_core/Timestamp.h"
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

/** A copy of `obs` with the time stamp `text` (seconds). */
mrpt::obs::CObservation3DRangeScan stamped(const mrpt::obs::CObservation3DRangeScan& obs,
                                           const std::string& text) {
  auto copy = obs;
  copy.timestamp = hrgbd::parseFrameTime(text);
  return copy;
}

/** Entries in `dir`. */
std::size_t files(const std::string& dir) {
  const std::filesystem::directory_iterator it(dir);
  return static_cast<std::size_t>(std::distance(begin(it), end(it)));
}

constexpr auto kOk = hrgbd::FrameResult::Status::Ok;
constexpr auto kLost = hrgbd::FrameResult::Status::TooFewMatches;

/** `log` is the one line of a timed step (rgbd_core/Progress.h): `what`, " ... ", its time. */
void expectStep(const std::string& log, const std::string& what) {
  EXPECT_EQ(log.rfind(what + " ... ", 0), 0u) << log;
  EXPECT_EQ(std::count(log.begin(), log.end(), '\n'), 1) << log;
  EXPECT_EQ(log.substr(log.size() - 3), " s\n") << log;
}

}  // namespace

TEST(TrajectorySink, WritesOneTumLinePerFrameWithTheFramesExactTimeStamp) {
  const auto dir = hrgbd::test::tempDir("trajectory_sink");
  hrgbd::RawlogSource src(kDesk);
  const auto first = stamped(*src.next(), "1.5");
  const auto second = stamped(*src.next(), "1700000000.1234567");  // beyond a double's 100 ns
  hrgbd::TrajectorySink sink(dir + "/t.txt", "# comment");
  sink.add(first, result(99, 0.25, kOk));  // the line's time is the frame's, not r.t
  sink.add(second, result(99, 0.5, kLost));
  // Under its name only once complete: a run that stops here leaves no trajectory.
  EXPECT_FALSE(std::filesystem::exists(dir + "/t.txt"));
  ASSERT_EQ(sink.trajectory().size(), 2u);
  EXPECT_EQ(sink.trajectory()[0].t, 1.5);
  sink.reset();
  EXPECT_TRUE(sink.trajectory().empty());
  std::ostringstream log;
  sink.finish(log);
  expectStep(log.str(), "trajectory: " + dir + "/t.txt");
  const auto text = lines(dir + "/t.txt");  // the file keeps what it has
  ASSERT_EQ(text.size(), 3u);
  EXPECT_EQ(text[0], "# comment");
  EXPECT_EQ(text[1], "1.500000000 0.250000 0.000000 0.000000 0.000000 0.000000 0.000000 1.000000");
  EXPECT_EQ(text[2].rfind("1700000000.123456700 0.500000 ", 0), 0u) << text[2];
  EXPECT_EQ(files(dir), 1u);  // no temporary file left
  EXPECT_THROW(hrgbd::TrajectorySink(dir + "/no/such/folder/t.txt", "#"), std::runtime_error);
}

TEST(TrajectorySink, ARunThatFailsLeavesNoTrajectoryAndKeepsThePreviousOne) {
  const auto dir = hrgbd::test::tempDir("trajectory_sink_fail");
  hrgbd::RawlogSource src(kDesk);
  const auto obs = src.next();
  std::ofstream(dir + "/t.txt") << "# previous run\n";
  {
    hrgbd::TrajectorySink sink(dir + "/t.txt", "# comment");
    sink.add(*obs, result(1, 0, kOk));
  }  // destroyed without finish(), as when the frame loop throws
  EXPECT_EQ(lines(dir + "/t.txt"), std::vector<std::string>{"# previous run"});
  EXPECT_EQ(files(dir), 1u);
  hrgbd::CsvSink csv(dir + "/f.csv");
  csv.add(*obs, result(1, 0, kOk));
  EXPECT_FALSE(std::filesystem::exists(dir + "/f.csv"));
}

TEST(TrajectorySink, WriteFailuresAreErrorsNamingTheFile) {
  hrgbd::RawlogSource src(kDesk);
  const auto obs = src.next();
  std::ostringstream log;
  try {  // /dev/full is written in place (not renamed over) and fails on the first flush
    hrgbd::TrajectorySink sink("/dev/full", "#");
    sink.add(*obs, result(1, 0, kOk));
    sink.finish(log);
    FAIL() << "writing /dev/full must fail";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("'/dev/full'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(hrgbd::CsvSink("/dev/full"), std::runtime_error);
  hrgbd::TrajectorySink null_sink("/dev/null", "#");  // a device that takes the data is fine
  null_sink.add(*obs, result(1, 0, kOk));
  EXPECT_NO_THROW(null_sink.finish(log));
  EXPECT_TRUE(std::filesystem::is_character_file("/dev/null"));
}

TEST(TrajectorySink, SaveWritesTheKeptPosesExactly) {
  const auto dir = hrgbd::test::tempDir("trajectory_sink_save");
  hrgbd::RawlogSource src(kDesk);
  hrgbd::TrajectorySink sink;
  sink.add(stamped(*src.next(), "1234567890.0000001"), result(0, 0.25, kOk));
  sink.save(dir + "/s.txt", "# saved");
  const auto text = lines(dir + "/s.txt");
  ASSERT_EQ(text.size(), 2u);
  EXPECT_EQ(text[1].rfind("1234567890.000000100 0.250000 ", 0), 0u) << text[1];
  EXPECT_THROW(sink.save("/dev/full", "#"), std::runtime_error);
}

TEST(CsvSink, OneRowPerFrameWithTheHeadersColumns) {
  const auto dir = hrgbd::test::tempDir("csv_sink");
  hrgbd::RawlogSource src(kDesk);
  hrgbd::CsvSink sink(dir + "/f.csv");
  auto r = result(1.5, 0.25, kLost);
  r.detail = "only 3 matches";
  r.path = {hrgbd::FramePath::Sparse::Photometric, hrgbd::FramePath::Refined::Refused};
  sink.add(stamped(*src.next(), "1.5"), r);
  std::ostringstream log;
  sink.finish(log);
  expectStep(log.str(), "CSV: " + dir + "/f.csv");
  const auto text = lines(dir + "/f.csv");
  ASSERT_EQ(text.size(), 2u);
  const auto commas = [](const std::string& s) { return std::count(s.begin(), s.end(), ','); };
  EXPECT_EQ(commas(text[0]), commas(text[1]));
  EXPECT_EQ(text[0].rfind("timestamp,status,path,refined,", 0), 0u) << text[0];
  EXPECT_EQ(text[1].rfind("1.500000000,too_few_matches,photometric,refused,", 0), 0u) << text[1];
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
  expectStep(log.str(), "map (PLY, " + std::to_string(points) + " points): " + dir + "/m.ply");
  const auto ply = lines(dir + "/m.ply");
  EXPECT_NE(std::find(ply.begin(), ply.end(), "element vertex " + std::to_string(points)),
            ply.end());
  sink.reset();
  EXPECT_EQ(sink.map().size(), 0u);
  EXPECT_TRUE(sink.path().empty());
}

TEST(ColouredMapSink, InSlamModeOnlyNodesEnterTheMapAndMoveWithTheirCorrection) {
  // keyframes_only: a registered keyframe of the tracker that is not a node stays out; a node's
  // cloud is kept (frozen: no longer inserted into) and re-inserted where the correction puts it
  hrgbd::RawlogSource src(kDesk);
  const auto obs = src.next();
  hrgbd::ColouredMapSink sink(hrgbd::MapParams(), {}, true);
  auto r = result(1, 0, kOk);
  r.keyframe = true;
  sink.add(*obs, r);
  EXPECT_EQ(sink.map().size(), 0u);
  r.node = true;
  sink.add(*obs, r);
  const auto points = sink.map().size();
  EXPECT_GT(points, 1000u);
  hrgbd::SlamPoses moved;
  moved.poses = {mrpt::poses::CPose3D(), mrpt::poses::CPose3D(0, 50, 0, 0, 0, 0)};
  sink.correct(moved);
  EXPECT_EQ(sink.map().size(), points);  // the same cloud, 50 m further along optical y
  float x, y, z;
  sink.map().points().getPoint(0, x, y, z);
  EXPECT_LT(z, -45.0f);  // MRPT z is optical -y
  // with a cloud spacing, a node seen from within it of a kept cloud adds nothing
  hrgbd::ColouredMapSink spaced(hrgbd::MapParams(), {}, true, 0.1);
  spaced.add(*obs, r);
  auto near = result(2, 0.05, kOk), far = result(3, 0.5, kOk);
  near.keyframe = near.node = far.keyframe = far.node = true;
  spaced.add(*obs, near);
  EXPECT_EQ(spaced.map().size(), points);
  spaced.add(*obs, far);
  EXPECT_GT(spaced.map().size(), points);
  hrgbd::ColouredMap frozen;
  frozen.insert(*obs, mrpt::poses::CPose3D());
  frozen.freeze();
  EXPECT_THROW(frozen.insert(*obs, mrpt::poses::CPose3D()), std::logic_error);
  hrgbd::ColouredMap again;
  // (points on a voxel's face may round into the next one and meet another: 2 of 6490 measured)
  EXPECT_GE(again.insert(frozen, mrpt::poses::CPose3D()), frozen.size() * 99 / 100);
}

TEST(ProgressSink, CountsFramesAndTheUnregisteredAndEndsTheLine) {
  hrgbd::RawlogSource src(kDesk);
  const auto obs = src.next();
  std::ostringstream out, log;
  double now = 0;
  hrgbd::ProgressParams p;
  p.total = 4;
  p.terminal = true;
  hrgbd::ProgressSink sink(out, p, [&] { return now; });
  now = 1, sink.add(*obs, result(1, 0, kOk));
  now = 2, sink.add(*obs, result(2, 0, kLost));
  sink.finish(log);
  EXPECT_EQ(out.str().back(), '\n');
  EXPECT_NE(out.str().find("\r2/4 frames (50%), 1.0 frames/s, 2.0 s left, 1 not registered"),
            std::string::npos)
      << out.str();
  EXPECT_NE(out.str().find("\r2 frames in 2.0 s, 1.0 frames/s, 1 not registered"),
            std::string::npos)
      << out.str();
  EXPECT_TRUE(log.str().empty());
}

TEST(ProgressSink, TheTotalIsTheSourcesFrameCountCutByMaxFrames) {
  hrgbd::RawlogSource src(kDesk);
  const auto all = src.frameCount();
  EXPECT_GT(all, 10u);
  std::size_t n = 0;
  while (src.next()) ++n;
  EXPECT_EQ(all, n) << "counted without loading images, as many as next() gives";
  EXPECT_EQ(src.frameCount(5), 5u);
  EXPECT_EQ(src.frameCount(all + 5), all);
  EXPECT_EQ(hrgbd::frameProgress(src, 0, "x").total, all);
  EXPECT_EQ(hrgbd::frameProgress(src, 5, "x").total, 5u);
  EXPECT_EQ(hrgbd::frameProgress(src, all + 5, "x").total, all);
  EXPECT_EQ(hrgbd::frameProgress(src, 0, "x").label, "x");
}

TEST(MapSinks, WriteFailuresAreErrorsAndUnfinishedFilesDoNotAppear) {
  const auto dir = hrgbd::test::tempDir("map_sinks_fail");
  hrgbd::RawlogSource src(kDesk);
  const auto obs = src.next();
  std::ostringstream log;
  for (const hrgbd::MapFiles& files : {hrgbd::MapFiles{"/dev/full", ""}, {"", "/dev/full"}}) {
    hrgbd::ColouredMapSink map(hrgbd::MapParams(), files);
    map.add(*obs, result(1, 0, kOk));
    EXPECT_THROW(map.finish(log), std::runtime_error) << files.ply << files.scene;
  }
  hrgbd::SimplemapSink simplemap("/dev/full");
  simplemap.add(*obs, result(1, 0, kOk));
  EXPECT_THROW(simplemap.finish(log), std::runtime_error);
  // A rawlog with external images beside it cannot be a device.
  EXPECT_THROW(hrgbd::PosedRawlogSink("/dev/null"), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists("/dev/null_Images"));
  {
    hrgbd::PosedRawlogSink rawlog(dir + "/p.rawlog");
    rawlog.add(*obs, result(1, 0, kOk));
  }  // not finished
  EXPECT_FALSE(std::filesystem::exists(dir + "/p.rawlog"));
  hrgbd::PosedRawlogSink rawlog(dir + "/q.rawlog");
  rawlog.add(*obs, result(1, 0, kOk));
  rawlog.finish(log);
  hrgbd::RawlogSource back(dir + "/q.rawlog");
  ASSERT_NE(back.next(), nullptr);
  EXPECT_EQ(back.next(), nullptr);
}
